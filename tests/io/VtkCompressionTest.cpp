// Compressed VTK export: a frame of a small column collapse written by VtkRunWriter takes at most
// half the bytes of the same data sets written uncompressed, and VTK's own readers give back
// every array unchanged.
#include "solver/io/CaseLoader.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Simulation.h"
#include "ui/vis/VtkDataSets.h"
#include "ui/vis/VtkRunWriter.h"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// Empty when a and b hold the same arrays (names, shapes, every value); else the first
/// difference.
QString compareArrays(vtkFieldData* a, vtkFieldData* b) {
    if (a->GetNumberOfArrays() != b->GetNumberOfArrays()) return "array count";
    for (int k = 0; k < a->GetNumberOfArrays(); ++k) {
        vtkAbstractArray* x = a->GetAbstractArray(k);
        vtkAbstractArray* y = b->GetAbstractArray(x->GetName());
        if (!y) return QString("no %1").arg(x->GetName());
        if (x->GetNumberOfValues() != y->GetNumberOfValues() ||
            x->GetNumberOfComponents() != y->GetNumberOfComponents() ||
            x->GetDataType() != y->GetDataType())
            return QString("%1: shape or type").arg(x->GetName());
        for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
            if (x->GetVariantValue(v) != y->GetVariantValue(v))
                return QString("%1[%2]").arg(x->GetName()).arg(v);
    }
    return {};
}

/// The size of the same data set in a file of the same kind: with no compression (raw appended
/// data), or zlib-compressed inline binary (base64, as the export wrote before).
template <class Writer>
std::uintmax_t sizeAs(vtkDataObject* data, const fs::path& path, bool inlineZlib) {
    vtkNew<Writer> writer;
    writer->SetInputData(data);
    writer->SetFileName(path.c_str());
    if (inlineZlib) {
        writer->SetDataModeToBinary();
        writer->SetCompressorTypeToZLib();
    } else {
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        writer->SetCompressorTypeToNone();
    }
    writer->Write();
    return fs::file_size(path);
}

template <class Reader> vtkSmartPointer<vtkDataSet> readBack(const fs::path& path) {
    vtkNew<Reader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

} // namespace

class VtkCompressionTest : public QObject {
    Q_OBJECT
private slots:
    void compressedFrameIsHalfAndReadsBackUnchanged() {
        // The default case shrunk to build in a moment, a few steps into its collapse.
        const solver::CaseSpec spec =
            io::loadCase(LBDEM_SOURCE_DIR "/sample_cases/default.toml",
                         {"grains.count=150", "grains.packing=0.79", "fluid.resolution=4",
                          "fluid.tau=0.506", "domain.width_m=0.08", "domain.height_m=0.04"});
        solver::Simulation simulation(spec, solver::makePlan(spec));
        for (int k = 0; k < 30; ++k)
            simulation.step();
        const solver::SnapshotPtr snapshot = simulation.snapshot();
        QVERIFY(snapshot->fluid);
        QTemporaryDir dir;
        const fs::path vtk = fs::path(dir.path().toStdString()) / "vtk";
        vis::VtkRunWriter(dir.path().toStdString()).write(*snapshot, 0);

        struct Part {
            const char* file;
            vtkSmartPointer<vtkDataSet> data;
            bool image;
        };
        const Part parts[] = {{"particles_000000.vtu", vis::particlesToVtk(*snapshot), false},
                              {"contacts_000000.vtu", vis::contactsToVtk(*snapshot), false},
                              {"outline_000000.vtu", vis::outlineToVtk(*snapshot), false},
                              {"fluid_000000.vti", vis::fluidToVtk(*snapshot->fluid), true}};
        std::uintmax_t compressed = 0, plain = 0, base64 = 0;
        for (const Part& part : parts) {
            const fs::path path = vtk / part.file;
            const fs::path reference = fs::path(dir.path().toStdString()) / part.file;
            compressed += fs::file_size(path);
            for (bool inlineZlib : {false, true})
                (inlineZlib ? base64 : plain) +=
                    part.image
                        ? sizeAs<vtkXMLImageDataWriter>(part.data, reference, inlineZlib)
                        : sizeAs<vtkXMLUnstructuredGridWriter>(part.data, reference, inlineZlib);
            const auto back = part.image ? readBack<vtkXMLImageDataReader>(path)
                                         : readBack<vtkXMLUnstructuredGridReader>(path);
            QVERIFY2(back && back->GetNumberOfPoints() == part.data->GetNumberOfPoints(),
                     part.file);
            for (auto [a, b] : {std::pair<vtkFieldData*, vtkFieldData*>{part.data->GetPointData(),
                                                                        back->GetPointData()},
                                {part.data->GetCellData(), back->GetCellData()},
                                {part.data->GetFieldData(), back->GetFieldData()}}) {
                const QString difference = compareArrays(a, b);
                QVERIFY2(difference.isEmpty(), qPrintable(QString(part.file) + ": " + difference));
            }
        }
        qInfo("frame: %llu bytes, uncompressed %llu (%.2f times), as inline zlib %llu (%.2f times)",
              static_cast<unsigned long long>(compressed), static_cast<unsigned long long>(plain),
              double(plain) / double(compressed), static_cast<unsigned long long>(base64),
              double(base64) / double(compressed));
        QVERIFY(2 * compressed <= plain);
        // Raw appended data saves the base64 third of inline binary.
        QVERIFY(compressed <= 0.8 * double(base64));
    }
};

QTEST_APPLESS_MAIN(VtkCompressionTest)
#include "VtkCompressionTest.moc"
