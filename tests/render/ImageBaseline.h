// Image regression helpers for the render tests: compare with a baseline, keep evidence on failure.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;

namespace lbdem::support {

/// Outcome of comparing a rendered image with tests/baselines/NAME.png.
struct BaselineResult {
    bool passed = false;
    double error = 0;    ///< vtkImageDifference's thresholded error
    std::string message; ///< why it failed, with the paths of the saved actual and diff images
};

/// Compares `actual` with tests/baselines/`name`.png using vtkImageDifference; above `tolerance`
/// (or without a baseline) the actual image and the difference image are written to
/// BUILD/Testing/Temporary/`name`.png and `name`.diff.png. With the environment variable
/// LBDEM_UPDATE_BASELINES=1 a failing or missing baseline is overwritten with `actual` instead
/// and the comparison passes (look at the new image before committing it).
BaselineResult compareWithBaseline(vtkImageData* actual, const std::string& name, double tolerance);

/// Reads a PNG file (RGB or RGBA) into an image; null when it cannot be read.
vtkSmartPointer<vtkImageData> readPng(const std::string& path);

/// Number of distinct RGB colours in `image`, a cheap measure that it is not blank.
int distinctColours(vtkImageData* image);

/// Number of pixels of `image` whose red, green and blue each lie within `tolerance` of (r, g, b).
int pixelsNear(vtkImageData* image, int r, int g, int b, int tolerance);

} // namespace lbdem::support
