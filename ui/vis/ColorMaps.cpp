// Colour maps built from a few control points interpolated in Lab space, as ParaView does.
#include "ui/vis/ColorMaps.h"

#include <vtkColorTransferFunction.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <array>
#include <filesystem>
#include <initializer_list>

namespace lbdem::vis {

namespace {

constexpr int kTableSize = 256;
constexpr const char* kUnicodeFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// A 256-entry table interpolating the (position, r, g, b) control points.
vtkSmartPointer<vtkLookupTable> tableFrom(std::initializer_list<std::array<double, 4>> points) {
    vtkNew<vtkColorTransferFunction> function;
    function->SetColorSpaceToLab();
    for (const auto& p : points)
        function->AddRGBPoint(p[0], p[1], p[2], p[3]);
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(kTableSize);
    for (int k = 0; k < kTableSize; ++k) {
        double rgb[3];
        function->GetColor(static_cast<double>(k) / (kTableSize - 1), rgb);
        table->SetTableValue(k, rgb[0], rgb[1], rgb[2], 1.0);
    }
    return table;
}

} // namespace

vtkSmartPointer<vtkLookupTable> makeSequentialLookupTable() {
    // Viridis at six stops (matplotlib's _viridis_data at 0, 0.2, ..., 1).
    return tableFrom({{0.0, 0.267, 0.005, 0.329},
                      {0.2, 0.254, 0.265, 0.530},
                      {0.4, 0.164, 0.471, 0.558},
                      {0.6, 0.135, 0.659, 0.518},
                      {0.8, 0.478, 0.821, 0.318},
                      {1.0, 0.993, 0.906, 0.144}});
}

vtkSmartPointer<vtkLookupTable> makeDivergingLookupTable() {
    // Moreland's cool-warm end points with a light grey centre.
    return tableFrom(
        {{0.0, 0.230, 0.299, 0.754}, {0.5, 0.865, 0.865, 0.865}, {1.0, 0.706, 0.016, 0.150}});
}

vtkSmartPointer<vtkLookupTable> makeGrainLookupTable() {
    // Cream to orange to brown: stays apart from viridis, so grains read on top of the fluid.
    return tableFrom({{0.0, 1.0, 0.96, 0.90}, {0.5, 0.96, 0.55, 0.15}, {1.0, 0.50, 0.15, 0.02}});
}

vtkSmartPointer<vtkLookupTable> makeForceLookupTable() {
    // Light to dark blue: the strongest chains are the darkest on the warm grain colours.
    return tableFrom({{0.0, 0.45, 0.65, 1.0}, {0.5, 0.10, 0.30, 0.85}, {1.0, 0.0, 0.03, 0.35}});
}

vtkSmartPointer<vtkScalarBarActor> makeColorBar(vtkLookupTable* table, const std::string& title) {
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(table);
    bar->SetTitle(title.c_str());
    bar->SetOrientationToHorizontal();
    bar->SetNumberOfLabels(3);
    bar->SetLabelFormat("%.3g");
    bar->SetBarRatio(0.3);
    bar->SetTextPositionToPrecedeScalarBar();
    bar->UnconstrainedFontSizeOn();
    for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
        text->SetFontSize(11);
        text->SetColor(0.1, 0.1, 0.1);
        text->BoldOff();
        text->ItalicOff();
        text->ShadowOff();
    }
    return bar;
}

bool useUnicodeFont(vtkTextProperty* text) {
    // VTK's embedded fonts have no Greek; a font file does (VTK_FONT_FILE family).
    if (!std::filesystem::exists(kUnicodeFont)) return false;
    text->SetFontFamily(VTK_FONT_FILE);
    text->SetFontFile(kUnicodeFont);
    return true;
}

std::string timeOverTcSymbol(bool unicode) {
    return unicode ? "t/\xcf\x84"
                     "c"
                   : "t/tau_c";
}

} // namespace lbdem::vis
