// Off-screen vtkRenderWindow -> vtkWindowToImageFilter -> PNG.
#include "ui/vis/OffscreenRenderer.h"

#include "solver/io/SafeFile.h"
#include "ui/vis/HeadlessDisplay.h"
#include "ui/vis/SceneView.h"
#include "ui/vis/VtkErrors.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace lbdem::vis {

OffscreenRenderer::OffscreenRenderer(int width, int height, const LayerSet& layers) {
    if (width < 16 || height < 16 || width > 16384 || height > 16384)
        throw std::invalid_argument("image size must be between 16 and 16384 pixels a side");
    ensureDisplay();
    m_view = std::make_unique<SceneView>();
    m_view->setLayers(layers);
    m_window = vtkSmartPointer<vtkRenderWindow>::New();
    m_window->SetOffScreenRendering(1);
    m_window->SetSize(width, height);
    m_window->SetMultiSamples(0); // identical pixels on every run, for the image tests
    m_window->AddRenderer(m_view->renderer());
}

OffscreenRenderer::~OffscreenRenderer() {
    if (m_window) m_window->Finalize();
}

vtkSmartPointer<vtkImageData> OffscreenRenderer::renderImage(const solver::Snapshot& snapshot) {
    m_view->update(snapshot);
    m_window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(m_window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(grab->GetOutput());
    return image;
}

void OffscreenRenderer::renderPng(const solver::Snapshot& snapshot, const std::string& path) {
    writePng(renderImage(snapshot), path);
}

void writePng(vtkImageData* image, const std::string& path) {
    const std::string temporary = path + ".tmp.png";
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(temporary.c_str());
    {
        const VtkErrorCatcher errors; // one sentence below instead of VTK's trace
        errno = 0;
        writer->Write();
        if (errors.failed() || writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary)) {
            const int cause =
                writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError ? ENOSPC : errno;
            std::remove(temporary.c_str());
            throw std::runtime_error("cannot write " + path + ": " +
                                     io::writeFailureCause(path, cause));
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) throw std::runtime_error("cannot replace " + path + ": " + error.message());
}

void renderSnapshotPng(const solver::Snapshot& snapshot, const std::string& path, int width,
                       int height, const LayerSet& layers) {
    OffscreenRenderer renderer(width, height, layers);
    renderer.renderPng(snapshot, path);
}

} // namespace lbdem::vis
