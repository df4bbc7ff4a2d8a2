// Lookup tables and colour bars shared by the layers, so every view uses the same colours.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkLookupTable;
class vtkScalarBarActor;
class vtkTextProperty;

namespace lbdem::vis {

/// A perceptually ordered map (viridis, sampled) for magnitudes such as speed.
vtkSmartPointer<vtkLookupTable> makeSequentialLookupTable();
/// A blue-white-red map for signed fields (pressure, vorticity), meant for symmetric ranges.
vtkSmartPointer<vtkLookupTable> makeDivergingLookupTable();
/// A cream-to-brown map for grain quantities, distinct from the fluid's viridis.
vtkSmartPointer<vtkLookupTable> makeGrainLookupTable();
/// A light-to-dark blue map for force chains, readable on top of the grain colours.
vtkSmartPointer<vtkLookupTable> makeForceLookupTable();
/// A horizontal colour bar for `table` titled `title` (which should carry the unit).
vtkSmartPointer<vtkScalarBarActor> makeColorBar(vtkLookupTable* table, const std::string& title);

/// Switches `text` to a font with Greek letters (DejaVu Sans) when installed; returns false (and
/// leaves the font alone) otherwise, so callers can fall back to ASCII such as "tau_c".
bool useUnicodeFont(vtkTextProperty* text);
/// "t/τc" when the Unicode font is available (see useUnicodeFont), else "t/tau_c".
std::string timeOverTcSymbol(bool unicode);

} // namespace lbdem::vis
