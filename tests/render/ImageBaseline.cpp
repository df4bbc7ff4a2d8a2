// Baseline comparison with vtkImageDifference (VTK's own regression-test tool in 9.1).
#include "tests/render/ImageBaseline.h"

#include "ui/vis/OffscreenRenderer.h"

#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>

namespace lbdem::support {

namespace {

/// True when LBDEM_UPDATE_BASELINES=1 asks to rewrite failing or missing baselines.
bool updatingBaselines() {
    const char* value = std::getenv("LBDEM_UPDATE_BASELINES");
    return value && std::strcmp(value, "1") == 0;
}

/// Writes `actual` as the new baseline and reports it as passed.
BaselineResult rewriteBaseline(vtkImageData* actual, const std::string& baselinePath,
                               double error) {
    vis::writePng(actual, baselinePath);
    BaselineResult result;
    result.passed = true;
    result.error = error;
    result.message = "LBDEM_UPDATE_BASELINES=1: wrote " + baselinePath;
    return result;
}

} // namespace

vtkSmartPointer<vtkImageData> readPng(const std::string& path) {
    if (!std::filesystem::exists(path)) return nullptr;
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    return image;
}

int distinctColours(vtkImageData* image) {
    int dims[3];
    image->GetDimensions(dims);
    const int components = image->GetNumberOfScalarComponents();
    std::set<int> colours;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            colours.insert(p[0] << 16 | p[1] << 8 | (components > 2 ? p[2] : p[0]));
        }
    return static_cast<int>(colours.size());
}

int pixelsNear(vtkImageData* image, int r, int g, int b, int tolerance) {
    int dims[3];
    image->GetDimensions(dims);
    int count = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            count += std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
                     std::abs(p[2] - b) <= tolerance;
        }
    return count;
}

BaselineResult compareWithBaseline(vtkImageData* actual, const std::string& name,
                                   double tolerance) {
    const std::string baselinePath =
        std::string(LBDEM_SOURCE_DIR) + "/tests/baselines/" + name + ".png";
    const std::string outDir = std::string(LBDEM_BINARY_DIR) + "/Testing/Temporary";
    std::filesystem::create_directories(outDir);
    const std::string actualPath = outDir + "/" + name + ".png";
    BaselineResult result;
    const auto baseline = readPng(baselinePath);
    if (!baseline && updatingBaselines()) return rewriteBaseline(actual, baselinePath, 0.0);
    if (!baseline) {
        vis::writePng(actual, actualPath);
        result.message = "no baseline " + baselinePath + "; look at " + actualPath +
                         " and copy it there if it is right";
        return result;
    }
    int a[3], b[3];
    actual->GetDimensions(a);
    baseline->GetDimensions(b);
    vtkNew<vtkImageDifference> difference;
    difference->SetInputData(actual);
    difference->SetImageData(baseline);
    difference->Update();
    result.error = difference->GetThresholdedError();
    result.passed = a[0] == b[0] && a[1] == b[1] && result.error <= tolerance;
    if (!result.passed && updatingBaselines())
        return rewriteBaseline(actual, baselinePath, result.error);
    if (!result.passed) {
        vis::writePng(actual, actualPath);
        const std::string diffPath = outDir + "/" + name + ".diff.png";
        if (a[0] == b[0] && a[1] == b[1]) vis::writePng(difference->GetOutput(), diffPath);
        result.message = name + ": thresholded error " + std::to_string(result.error) + " > " +
                         std::to_string(tolerance) + " (or size differs); see " + actualPath +
                         " and " + diffPath;
    }
    return result;
}

} // namespace lbdem::support
