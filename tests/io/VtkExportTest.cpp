// VTU/VTI/PVD export: a synthetic series written by VtkRunWriter reads back with VTK's readers.
#include "solver/core/InputError.h"
#include "tests/support/SyntheticSnapshot.h"
#include "ui/vis/PvdSeries.h"
#include "ui/vis/VtkRunReader.h"
#include "ui/vis/VtkRunWriter.h"

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace lbdem;

class VtkExportTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void pvdSeriesListEveryFrame();
    void particlesReadBack();
    void contactsReadBack();
    void fluidReadBack();
    void outlineReadBack();
    void filesAreCompressedRawAppended();
    void runReaderRebuildsSnapshot();
    void dryRunHasNoFluidSeries();
    void resumeContinuesNumbering();
    void resumeDropsFramesAfterCheckpoint();

private:
    vtkSmartPointer<vtkUnstructuredGrid> readGrid(const std::string& name) const;
    std::string m_vtk;
    QTemporaryDir m_dir;
    static constexpr int kFrames = 3;
};

void VtkExportTest::initTestCase() {
    // Writing must never need a display (docs/design.md §8): run the whole test without one.
    ::unsetenv("DISPLAY");
    QVERIFY(m_dir.isValid());
    support::writeSyntheticRun(m_dir.path().toStdString(), kFrames);
    m_vtk = m_dir.path().toStdString() + "/vtk";
}

vtkSmartPointer<vtkUnstructuredGrid> VtkExportTest::readGrid(const std::string& name) const {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((m_vtk + "/" + name).c_str());
    reader->Update();
    return reader->GetOutput();
}

void VtkExportTest::pvdSeriesListEveryFrame() {
    for (const char* series : {"particles", "contacts", "fluid", "outline"}) {
        const auto entries = vis::readPvd(m_vtk + "/" + series + ".pvd");
        QCOMPARE(static_cast<int>(entries.size()), kFrames);
        for (int k = 0; k < kFrames; ++k) {
            QCOMPARE(entries[k].time_s, support::syntheticSnapshot(k).time_s);
            QVERIFY(std::filesystem::exists(m_vtk + "/" + entries[k].file));
        }
    }
    QCOMPARE(vis::readPvd(m_vtk + "/fluid.pvd")[1].file, std::string("fluid_000001.vti"));
    for (const auto& file : std::filesystem::directory_iterator(m_vtk))
        QVERIFY2(file.path().extension() != ".tmp", file.path().c_str());
}

void VtkExportTest::particlesReadBack() {
    const solver::Snapshot expected = support::syntheticSnapshot(2);
    const auto grid = readGrid("particles_000002.vtu");
    QVERIFY(expected.grains.size() > 200);
    QCOMPARE(grid->GetNumberOfPoints(), static_cast<vtkIdType>(expected.grains.size()));
    QCOMPARE(grid->GetNumberOfCells(), static_cast<vtkIdType>(expected.grains.size()));
    vtkPointData* pd = grid->GetPointData();
    for (const char* name :
         {"radius", "velocity", "omega", "force", "speed", "contact_force", "hydro_force"})
        QVERIFY2(pd->GetArray(name), name);
    QCOMPARE(pd->GetArray("velocity")->GetNumberOfComponents(), 3);
    const vtkIdType k = 17;
    QCOMPARE(static_cast<float>(pd->GetArray("radius")->GetComponent(k, 0)),
             expected.grains.radius[k]);
    QCOMPARE(static_cast<float>(pd->GetArray("velocity")->GetComponent(k, 1)),
             expected.grains.vy[k]);
    QCOMPARE(static_cast<float>(pd->GetArray("omega")->GetComponent(k, 0)),
             expected.grains.omega[k]);
    QCOMPARE(static_cast<float>(grid->GetPoint(k)[0]), expected.grains.x[k]);
    QCOMPARE(grid->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), expected.time_s);
}

void VtkExportTest::contactsReadBack() {
    const solver::Snapshot expected = support::syntheticSnapshot(1);
    const auto grid = readGrid("contacts_000001.vtu");
    QCOMPARE(grid->GetNumberOfCells(), static_cast<vtkIdType>(expected.contacts.size()));
    vtkCellData* cd = grid->GetCellData();
    QVERIFY(cd->GetArray("normal_force") && cd->GetArray("tangential_force"));
    int walls = 0;
    for (vtkIdType k = 0; k < grid->GetNumberOfCells(); ++k) {
        QCOMPARE(static_cast<float>(cd->GetArray("normal_force")->GetComponent(k, 0)),
                 expected.contacts.normal_force[k]);
        QCOMPARE(grid->GetCell(k)->GetNumberOfPoints(), vtkIdType(2));
        if (expected.contacts.j[k] >= 0) continue;
        ++walls; // a wall contact ends on its wall point
        const double* end = grid->GetPoint(grid->GetCell(k)->GetPointId(1));
        QCOMPARE(static_cast<float>(end[0]), expected.contacts.wx[k]);
        QCOMPARE(static_cast<float>(end[1]), expected.contacts.wy[k]);
    }
    QVERIFY(walls > 5);
}

void VtkExportTest::fluidReadBack() {
    const solver::Snapshot expected = support::syntheticSnapshot(0);
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName((m_vtk + "/fluid_000000.vti").c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    QCOMPARE(dims[0], expected.fluid->nx);
    QCOMPARE(dims[1], expected.fluid->ny);
    QCOMPARE(dims[2], 1);
    QCOMPARE(static_cast<float>(image->GetSpacing()[0]), expected.fluid->spacing_m);
    vtkPointData* pd = image->GetPointData();
    for (const char* name : {"velocity", "pressure", "vorticity", "solid_fraction"})
        QVERIFY2(pd->GetArray(name), name);
    const vtkIdType k = 30 * expected.fluid->nx + 55; // x fastest, as in SnapshotFluid
    QCOMPARE(static_cast<float>(pd->GetArray("velocity")->GetComponent(k, 0)),
             expected.fluid->ux[k]);
    QCOMPARE(static_cast<float>(pd->GetArray("pressure")->GetComponent(k, 0)),
             expected.fluid->pressure[k]);
    QCOMPARE(static_cast<float>(pd->GetArray("vorticity")->GetComponent(k, 0)),
             expected.fluid->vorticity[k]);
    QCOMPARE(static_cast<float>(pd->GetArray("solid_fraction")->GetComponent(0, 0)), 0.6f);
}

void VtkExportTest::outlineReadBack() {
    const solver::Snapshot expected = support::syntheticSnapshot(2);
    const auto grid = readGrid("outline_000002.vtu");
    QCOMPARE(grid->GetNumberOfCells(), vtkIdType(1));
    QCOMPARE(grid->GetCellType(0), static_cast<int>(VTK_POLY_LINE));
    QCOMPARE(grid->GetNumberOfPoints(), static_cast<vtkIdType>(expected.outline.size()));
}

void VtkExportTest::filesAreCompressedRawAppended() {
    std::ifstream in(m_vtk + "/particles_000000.vtu");
    const std::string head((std::istreambuf_iterator<char>(in)), {});
    QVERIFY(head.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos);
    QVERIFY(head.find("format=\"appended\"") != std::string::npos);
    QVERIFY(head.find("encoding=\"raw\"") != std::string::npos);
}

void VtkExportTest::runReaderRebuildsSnapshot() {
    const vis::VtkRunReader reader(m_dir.path().toStdString());
    QCOMPARE(reader.frameCount(), kFrames);
    QCOMPARE(reader.frameNearestTime(0.026), 1);
    const solver::Snapshot expected = support::syntheticSnapshot(2);
    const solver::Snapshot back = reader.read(2);
    QCOMPARE(back.case_name, expected.case_name);
    QCOMPARE(back.step, expected.step);
    QCOMPARE(back.tc_s, expected.tc_s);
    QCOMPARE(back.domain_width_m, expected.domain_width_m);
    QCOMPARE(back.grains.x, expected.grains.x);
    QCOMPARE(back.grains.radius, expected.grains.radius);
    QCOMPARE(back.grains.hydro_fx, expected.grains.hydro_fx);
    QCOMPARE(back.contacts.i, expected.contacts.i);
    QCOMPARE(back.contacts.j, expected.contacts.j);
    QCOMPARE(back.contacts.tangential_force, expected.contacts.tangential_force);
    QVERIFY(back.fluid.has_value());
    QCOMPARE(back.fluid->vorticity, expected.fluid->vorticity);
    QCOMPARE(back.outline, expected.outline);
    QCOMPARE(back.walls.size(), expected.walls.size());
    QCOMPARE(back.metrics.at("runout_m"), expected.metrics.at("runout_m"));
    QVERIFY_EXCEPTION_THROWN(reader.read(kFrames), solver::InputError);
}

void VtkExportTest::dryRunHasNoFluidSeries() {
    QTemporaryDir dir;
    support::writeSyntheticRun(dir.path().toStdString(), 2, false);
    QVERIFY(!std::filesystem::exists(dir.path().toStdString() + "/vtk/fluid.pvd"));
    const vis::VtkRunReader reader(dir.path().toStdString());
    QVERIFY(!reader.read(1).fluid.has_value());
}

void VtkExportTest::resumeContinuesNumbering() {
    QTemporaryDir dir;
    support::writeSyntheticRun(dir.path().toStdString(), 2);
    vis::VtkRunWriter resumed(dir.path().toStdString(), true);
    QCOMPARE(resumed.frameCount(), 2);
    QCOMPARE(resumed.write(support::syntheticSnapshot(2)), 2);
    const auto entries = vis::readPvd(dir.path().toStdString() + "/vtk/particles.pvd");
    QCOMPARE(static_cast<int>(entries.size()), 3);
    QCOMPARE(entries[2].file, std::string("particles_000002.vtu"));
}

void VtkExportTest::resumeDropsFramesAfterCheckpoint() {
    // A run killed after writing frames 0-2 resumes from a checkpoint at frame 1's time: frame 2
    // leaves the series and is written again under its own number, never twice.
    QTemporaryDir dir;
    support::writeSyntheticRun(dir.path().toStdString(), 3);
    const auto before = vis::readPvd(dir.path().toStdString() + "/vtk/particles.pvd");
    vis::VtkRunWriter resumed(dir.path().toStdString(), true, before[1].time_s);
    QCOMPARE(resumed.frameCount(), 2);
    QCOMPARE(resumed.write(support::syntheticSnapshot(2), 2), 2);
    for (const char* series : {"particles", "contacts", "fluid", "outline"}) {
        const auto entries = vis::readPvd(dir.path().toStdString() + "/vtk/" + series + ".pvd");
        QCOMPARE(static_cast<int>(entries.size()), 3);
        QCOMPARE(entries[2].time_s, before[2].time_s);
        QVERIFY(entries[2].file.find("_000002.") != std::string::npos);
    }
}

QTEST_GUILESS_MAIN(VtkExportTest)
#include "VtkExportTest.moc"
