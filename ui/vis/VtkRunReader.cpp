// Run-folder reader: .pvd index, then VTK XML readers for each data set of a frame.
#include "ui/vis/VtkRunReader.h"

#include "solver/core/InputError.h"
#include "ui/vis/VtkDataSets.h"
#include "ui/vis/VtkErrors.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>

namespace lbdem::vis {

namespace {

/// The file of the same frame in another series: particles_000012.vtu -> contacts_000012.vtu.
std::string siblingFile(const std::string& particlesFile, const std::string& series,
                        const std::string& extension) {
    const auto underscore = particlesFile.rfind('_');
    const auto dot = particlesFile.rfind('.');
    if (underscore == std::string::npos || dot == std::string::npos || dot < underscore) return {};
    return series + particlesFile.substr(underscore, dot - underscore) + "." + extension;
}

/// Run a reader of path; throws InputError naming the file when VTK reports an error (a damaged
/// or truncated file), so that nothing is drawn from a partial data set.
void updateReader(vtkXMLReader* reader, const std::string& path) {
    const VtkErrorCatcher errors;
    reader->Update();
    if (errors.failed() || reader->GetErrorCode() != vtkErrorCode::NoError)
        throw solver::InputError(
            path + " is damaged or not a VTK file written by lbdem" +
            (errors.firstError().empty() ? std::string() : " (" + errors.firstError() + ")"));
}

/// Reads an unstructured grid, or returns null when the file does not exist.
vtkSmartPointer<vtkUnstructuredGrid> readGrid(const std::string& path, bool required) {
    if (!std::filesystem::exists(path)) {
        if (required) throw solver::InputError("missing VTK file " + path);
        return nullptr;
    }
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    updateReader(reader, path);
    vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
    if (!grid || (required && grid->GetPointData()->GetArray("radius") == nullptr &&
                  grid->GetNumberOfPoints() > 0))
        throw solver::InputError(path + " is not a particles file written by lbdem");
    return grid;
}

} // namespace

VtkRunReader::VtkRunReader(const std::string& runDir) {
    namespace fs = std::filesystem;
    if (fs::exists(fs::path(runDir) / "vtk" / "particles.pvd"))
        m_dir = (fs::path(runDir) / "vtk").string();
    else if (fs::exists(fs::path(runDir) / "particles.pvd"))
        m_dir = runDir;
    else
        throw solver::InputError("no VTK output in " + runDir +
                                 " (expected vtk/particles.pvd, written by lbdem run)");
    m_frames = readPvd(m_dir + "/particles.pvd");
    if (m_frames.empty()) throw solver::InputError(m_dir + "/particles.pvd lists no frames yet");
}

int VtkRunReader::frameNearestTime(double time_s) const {
    int best = -1;
    double distance = INFINITY;
    for (int k = 0; k < frameCount(); ++k)
        if (std::abs(frameTime(k) - time_s) < distance) {
            distance = std::abs(frameTime(k) - time_s);
            best = k;
        }
    if (best < 0) throw solver::InputError("the run has no frames");
    return best;
}

solver::Snapshot VtkRunReader::read(int frame) const {
    if (frame < 0 || frame >= frameCount())
        throw solver::InputError("frame " + std::to_string(frame) +
                                 " does not exist; the run has " + std::to_string(frameCount()) +
                                 " frames (0.." + std::to_string(frameCount() - 1) + ")");
    const std::string particlesFile = m_frames[static_cast<std::size_t>(frame)].file;
    const auto particles = readGrid(m_dir + "/" + particlesFile, true);
    const auto contacts =
        readGrid(m_dir + "/" + siblingFile(particlesFile, "contacts", "vtu"), false);
    const auto outline =
        readGrid(m_dir + "/" + siblingFile(particlesFile, "outline", "vtu"), false);
    vtkSmartPointer<vtkImageData> fluid;
    const std::string fluidPath = m_dir + "/" + siblingFile(particlesFile, "fluid", "vti");
    if (std::filesystem::exists(fluidPath)) {
        vtkNew<vtkXMLImageDataReader> reader;
        reader->SetFileName(fluidPath.c_str());
        updateReader(reader, fluidPath);
        fluid = reader->GetOutput();
    }
    solver::Snapshot snapshot = snapshotFromVtk(particles, contacts, fluid, outline);
    snapshot.time_s = frameTime(frame);
    return snapshot;
}

} // namespace lbdem::vis
