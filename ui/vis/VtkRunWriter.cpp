// VTK XML output of a run: zlib-compressed raw appended data sets, atomically renamed, plus .pvd
// series.
#include "ui/vis/VtkRunWriter.h"

#include "solver/io/SafeFile.h"
#include "ui/vis/VtkDataSets.h"
#include "ui/vis/VtkErrors.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace lbdem::vis {

namespace {

/// zlib's level: on a lattice frame 9 saves about 1 % more than 5 at several times the cost, and
/// LZ4 is faster but leaves the file a third larger.
constexpr int kCompressionLevel = 5;

/// Writes `data` with `writer` to `dir`/`name` through a temporary file and a rename; on failure
/// (a full disk) the temporary file is removed, the frame in place (if any) stays, and one
/// sentence says why instead of VTK's trace.
void writeDataSet(vtkXMLWriter* writer, vtkDataObject* data, const std::string& dir,
                  const std::string& name) {
    const std::string path = dir + "/" + name;
    const std::string temporary = path + ".tmp";
    writer->SetInputData(data);
    writer->SetFileName(temporary.c_str());
    // Raw appended data: inline binary is base64, a third larger than the compressed bytes.
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetHeaderTypeToUInt64(); // blocks of a large lattice may pass 4 GiB uncompressed
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(kCompressionLevel);
    const VtkErrorCatcher errors;
    errno = 0;
    const bool written =
        writer->Write() == 1 && !errors.failed() && writer->GetErrorCode() == vtkErrorCode::NoError;
    if (!written) {
        const int cause =
            writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError ? ENOSPC : errno;
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path + ": " +
                                 io::writeFailureCause(path, cause));
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot replace " + path + ": " + error.message());
    }
}

/// Writes an unstructured grid as .vtu.
void writeGrid(vtkUnstructuredGrid* grid, const std::string& dir, const std::string& name) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writeDataSet(writer, grid, dir, name);
}

} // namespace

std::string vtkFrameFileName(const std::string& series, int frame, const std::string& extension) {
    char number[16];
    std::snprintf(number, sizeof number, "%06d", frame);
    return series + "_" + number + "." + extension;
}

VtkRunWriter::VtkRunWriter(const std::string& runDir, bool resume, double keepUntilS)
    : m_dir(runDir + "/vtk"), m_particles(m_dir + "/particles.pvd", resume),
      m_contacts(m_dir + "/contacts.pvd", resume), m_fluid(m_dir + "/fluid.pvd", resume),
      m_outline(m_dir + "/outline.pvd", resume) {
    std::error_code error;
    std::filesystem::create_directories(m_dir, error);
    if (error) throw std::runtime_error("cannot create " + m_dir + ": " + error.message());
    for (PvdSeries* series : {&m_particles, &m_contacts, &m_fluid, &m_outline})
        series->dropAfter(keepUntilS);
    m_frame = static_cast<int>(m_particles.entries().size());
}

int VtkRunWriter::write(const solver::Snapshot& snapshot) {
    return write(snapshot, m_frame);
}

int VtkRunWriter::write(const solver::Snapshot& snapshot, int frame) {
    const double t = snapshot.time_s;
    // The particles series goes last: readers take its entries as the list of complete frames.
    const std::string contacts = vtkFrameFileName("contacts", frame, "vtu");
    writeGrid(contactsToVtk(snapshot), m_dir, contacts);
    m_contacts.append(t, contacts);
    if (snapshot.fluid) {
        const std::string fluid = vtkFrameFileName("fluid", frame, "vti");
        vtkNew<vtkXMLImageDataWriter> writer;
        writeDataSet(writer, fluidToVtk(*snapshot.fluid), m_dir, fluid);
        m_fluid.append(t, fluid);
    }
    const std::string outline = vtkFrameFileName("outline", frame, "vtu");
    writeGrid(outlineToVtk(snapshot), m_dir, outline);
    m_outline.append(t, outline);
    const std::string particles = vtkFrameFileName("particles", frame, "vtu");
    writeGrid(particlesToVtk(snapshot), m_dir, particles);
    m_particles.append(t, particles);
    m_frame = std::max(m_frame, frame) + 1;
    return frame;
}

} // namespace lbdem::vis
