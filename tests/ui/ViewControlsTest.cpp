// The view controls' colour ranges: ticking "fixed" keeps the fitted range and emits it, edits
// apply at once, an inverted range is not applied, each field keeps its own range, and the view
// options survive a round trip through QSettings.
#include "ui/studio/ViewControls.h"
#include "ui/studio/ViewSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using lbdem::studio::ViewControls;
namespace vis = lbdem::vis;

Q_DECLARE_METATYPE(lbdem::vis::LayerSet)

namespace {

/// The child of `controls` named `name`; fails the test when missing.
template <typename Widget> Widget* part(ViewControls& controls, const char* name) {
    auto* widget = controls.findChild<Widget*>(name);
    if (!widget) qFatal("no child %s", name);
    return widget;
}

/// The layers of the latest layersChanged emission.
vis::LayerSet lastEmitted(const QSignalSpy& spy) {
    return spy.last().at(0).value<vis::LayerSet>();
}

} // namespace

class ViewControlsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<vis::LayerSet>("lbdem::vis::LayerSet"); }

    void fixingKeepsTheFittedRange() {
        ViewControls controls;
        QSignalSpy changed(&controls, &ViewControls::layersChanged);
        controls.showColorRanges({false, 0.0, 0.0123456}, {false, 0.0, 2.5e-5});
        QVERIFY(changed.isEmpty()); // showing the fitted range changes nothing
        auto* max = part<QDoubleSpinBox>(controls, "fluidRangeMax");
        QVERIFY(!max->isEnabled());
        QCOMPARE(max->value(), 0.01235); // rounded to the digits shown
        QCOMPARE(part<QDoubleSpinBox>(controls, "grainRangeMax")->text(), QString("2.5e-05"));

        part<QCheckBox>(controls, "fluidRangeFixed")->setChecked(true);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(lastEmitted(changed).fluidRange(), (vis::ColorRange{true, 0.0, 0.01235}));
        QVERIFY(!lastEmitted(changed).grainRange().fixed);
        QVERIFY(max->isEnabled());
        // A fixed range no longer follows the frames.
        controls.showColorRanges({false, 0.0, 0.5}, {false, 0.0, 1.0});
        QCOMPARE(max->value(), 0.01235);

        max->setValue(0.02);
        QCOMPARE(lastEmitted(changed).fluidRange(), (vis::ColorRange{true, 0.0, 0.02}));
        const int before = changed.count();
        part<QDoubleSpinBox>(controls, "fluidRangeMin")->setValue(0.05); // above max
        QCOMPARE(changed.count(), before);
        QCOMPARE(controls.layers().fluidRange(), (vis::ColorRange{true, 0.0, 0.02}));
        part<QDoubleSpinBox>(controls, "fluidRangeMin")->setValue(-0.01);
        QCOMPARE(lastEmitted(changed).fluidRange(), (vis::ColorRange{true, -0.01, 0.02}));

        part<QCheckBox>(controls, "fluidRangeFixed")->setChecked(false);
        QVERIFY(!lastEmitted(changed).fluidRange().fixed);
    }

    void typedValuesInAnyNotation() {
        ViewControls controls;
        part<QCheckBox>(controls, "grainRangeFixed")->setChecked(true);
        auto* max = part<QDoubleSpinBox>(controls, "grainRangeMax");
        max->findChild<QLineEdit*>()->selectAll();
        QTest::keyClicks(max, "3.5e-4");
        QTest::keyClick(max, Qt::Key_Enter);
        QCOMPARE(max->value(), 3.5e-4);
        QCOMPARE(controls.layers().grainRange().max, 3.5e-4);
    }

    void eachFieldKeepsItsRange() {
        ViewControls controls;
        QSignalSpy changed(&controls, &ViewControls::layersChanged);
        part<QCheckBox>(controls, "fluidRangeFixed")->setChecked(true);
        part<QDoubleSpinBox>(controls, "fluidRangeMax")->setValue(0.3);
        auto* field = part<QComboBox>(controls, "fluidField");
        field->setCurrentIndex(static_cast<int>(vis::FluidField::Pressure));
        QCOMPARE(lastEmitted(changed).fluidField, vis::FluidField::Pressure);
        QVERIFY(!lastEmitted(changed).fluidRange().fixed);
        QVERIFY(!part<QCheckBox>(controls, "fluidRangeFixed")->isChecked());
        field->setCurrentIndex(static_cast<int>(vis::FluidField::Speed));
        QCOMPARE(lastEmitted(changed).fluidRange(), (vis::ColorRange{true, 0.0, 0.3}));
        QVERIFY(part<QCheckBox>(controls, "fluidRangeFixed")->isChecked());
        QCOMPARE(part<QDoubleSpinBox>(controls, "fluidRangeMax")->value(), 0.3);
    }

    void setLayersShowsTheRanges() {
        ViewControls controls;
        QSignalSpy changed(&controls, &ViewControls::layersChanged);
        vis::LayerSet layers;
        layers.grainColoring = vis::GrainColoring::ContactForce;
        layers.grainRange() = {true, 2.0, 40.0};
        layers.chains = false;
        controls.setLayers(layers);
        QVERIFY(changed.isEmpty());
        QCOMPARE(controls.layers().grainRange(), layers.grainRange());
        QVERIFY(!controls.layers().chains);
        QVERIFY(part<QCheckBox>(controls, "grainRangeFixed")->isChecked());
        QCOMPARE(part<QDoubleSpinBox>(controls, "grainRangeMin")->value(), 2.0);
    }

    void settingsRoundTrip() {
        QTemporaryDir dir;
        QSettings settings(dir.filePath("view.ini"), QSettings::IniFormat);
        vis::LayerSet layers = vis::parseLayerSet("fluid,grains,streamlines");
        layers.fluidField = vis::FluidField::Vorticity;
        layers.grainColoring = vis::GrainColoring::ContactForce;
        layers.fluidRanges[static_cast<int>(vis::FluidField::Speed)] = {true, 0.0, 0.05};
        layers.fluidRanges[static_cast<int>(vis::FluidField::Vorticity)] = {true, -20.0, 20.0};
        layers.grainRanges[static_cast<int>(vis::GrainColoring::ContactForce)] = {false, 1.0, 3.0};
        lbdem::studio::saveViewSettings(settings, layers);
        const vis::LayerSet loaded = lbdem::studio::loadViewSettings(settings, vis::LayerSet{});
        QCOMPARE(lbdem::vis::layerSetToString(loaded), std::string("fluid,grains,streamlines"));
        QCOMPARE(loaded.fluidField, layers.fluidField);
        QCOMPARE(loaded.grainColoring, layers.grainColoring);
        for (std::size_t k = 0; k < layers.fluidRanges.size(); ++k)
            QCOMPARE(loaded.fluidRanges[k], layers.fluidRanges[k]);
        for (std::size_t k = 0; k < layers.grainRanges.size(); ++k)
            QCOMPARE(loaded.grainRanges[k], layers.grainRanges[k]);

        // Entries from another version or edited by hand keep their defaults, one by one.
        settings.setValue("view/fluidField", "density");
        settings.setValue("view/range/fluid/speed/max", -1.0); // not above min
        settings.setValue("view/range/fluid/pressure/fixed", true);
        settings.setValue("view/range/fluid/pressure/min", "low");
        const vis::LayerSet fallback = lbdem::studio::loadViewSettings(settings, vis::LayerSet{});
        QCOMPARE(fallback.fluidField, vis::FluidField::Speed);
        QCOMPARE(fallback.fluidRanges[0], vis::ColorRange{});
        QCOMPARE(fallback.fluidRanges[1], vis::ColorRange{});
        QCOMPARE(fallback.fluidRanges[2], (vis::ColorRange{true, -20.0, 20.0}));
        QCOMPARE(fallback.grainColoring, vis::GrainColoring::ContactForce);
    }
};

QTEST_MAIN(ViewControlsTest)
#include "ViewControlsTest.moc"
