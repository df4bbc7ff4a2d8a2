// Snapshot <-> VTK data sets; the only place that knows the array names of the written files.
#include "ui/vis/VtkDataSets.h"

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace lbdem::vis {

namespace {

constexpr const char* kMetricPrefix = "metric.";

/// A float array named `name` with `components` components and `tuples` tuples.
vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, vtkIdType tuples) {
    auto array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(tuples);
    array->FillValue(0.0f); // a Snapshot array shorter than the count leaves zeros, not garbage
    return array;
}

/// A one-value double array for field data.
void addFieldValue(vtkFieldData* data, const char* name, double value) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name);
    array->InsertNextValue(value);
    data->AddArray(array);
}

/// The first value of a field-data array, or `fallback` when it is absent.
double fieldValue(vtkFieldData* data, const char* name, double fallback) {
    vtkDataArray* array = data ? data->GetArray(name) : nullptr;
    return array && array->GetNumberOfTuples() > 0 ? array->GetComponent(0, 0) : fallback;
}

/// Copies a vector of floats into component `component` of `array` (at most its tuple count).
void fill(vtkFloatArray* array, const std::vector<float>& values, int component = 0) {
    const auto count =
        std::min(values.size(), static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (std::size_t k = 0; k < count; ++k)
        array->SetTypedComponent(static_cast<vtkIdType>(k), component, values[k]);
}

/// Reads component `component` of the named array into a vector (empty when absent).
std::vector<float> column(vtkDataSetAttributes* data, const char* name, int component = 0) {
    vtkDataArray* array = data ? data->GetArray(name) : nullptr;
    std::vector<float> values;
    if (!array) return values;
    values.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (vtkIdType k = 0; k < array->GetNumberOfTuples(); ++k)
        values[static_cast<std::size_t>(k)] = static_cast<float>(array->GetComponent(k, component));
    return values;
}

/// Scene-wide values that a re-render needs, stored as field data on the particles file.
void addSceneFieldData(const solver::Snapshot& s, vtkFieldData* data) {
    addFieldValue(data, "TimeValue", s.time_s); // the name ParaView looks for
    addFieldValue(data, "step", static_cast<double>(s.step));
    addFieldValue(data, "tc_s", s.tc_s);
    addFieldValue(data, "domain_width_m", s.domain_width_m);
    addFieldValue(data, "domain_height_m", s.domain_height_m);
    addFieldValue(data, "slope_deg", s.slope_deg);
    vtkNew<vtkStringArray> name;
    name->SetName("case_name");
    name->InsertNextValue(s.case_name);
    data->AddArray(name);
    auto walls = floatArray("walls", 4, static_cast<vtkIdType>(s.walls.size()));
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
        const auto& w = s.walls[k];
        const float tuple[4] = {w.x0, w.y0, w.x1, w.y1};
        walls->SetTypedTuple(static_cast<vtkIdType>(k), tuple);
    }
    data->AddArray(walls);
    for (const auto& [key, value] : s.metrics)
        addFieldValue(data, (kMetricPrefix + key).c_str(), value);
}

/// Reads back what addSceneFieldData stored.
void readSceneFieldData(vtkFieldData* data, solver::Snapshot& s) {
    s.time_s = fieldValue(data, "TimeValue", 0);
    s.step = static_cast<long long>(std::llround(fieldValue(data, "step", 0)));
    s.tc_s = fieldValue(data, "tc_s", 0);
    s.domain_width_m = fieldValue(data, "domain_width_m", 0);
    s.domain_height_m = fieldValue(data, "domain_height_m", 0);
    s.slope_deg = fieldValue(data, "slope_deg", 0);
    if (auto* name = vtkStringArray::SafeDownCast(data->GetAbstractArray("case_name"));
        name && name->GetNumberOfValues() > 0)
        s.case_name = name->GetValue(0);
    if (vtkDataArray* walls = data->GetArray("walls"); walls && walls->GetNumberOfComponents() == 4)
        for (vtkIdType k = 0; k < walls->GetNumberOfTuples(); ++k)
            s.walls.push_back({static_cast<float>(walls->GetComponent(k, 0)),
                               static_cast<float>(walls->GetComponent(k, 1)),
                               static_cast<float>(walls->GetComponent(k, 2)),
                               static_cast<float>(walls->GetComponent(k, 3))});
    const std::string prefix = kMetricPrefix;
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
        const char* name = data->GetArrayName(a);
        if (name && std::string(name).rfind(prefix, 0) == 0)
            s.metrics[std::string(name).substr(prefix.size())] = fieldValue(data, name, 0);
    }
}

/// Sum of the normal forces acting on each grain.
std::vector<float> contactForcePerGrain(const solver::Snapshot& s) {
    std::vector<float> sum(s.grains.size(), 0.0f);
    const auto n = static_cast<std::int32_t>(sum.size());
    for (std::size_t k = 0; k < s.contacts.size(); ++k) {
        const float f = s.contacts.normal_force[k];
        if (s.contacts.i[k] >= 0 && s.contacts.i[k] < n)
            sum[static_cast<std::size_t>(s.contacts.i[k])] += f;
        if (s.contacts.j[k] >= 0 && s.contacts.j[k] < n)
            sum[static_cast<std::size_t>(s.contacts.j[k])] += f;
    }
    return sum;
}

} // namespace

std::pair<float, float> wallContactPoint(const solver::SnapshotContacts& contacts, std::size_t k,
                                         std::size_t wallOrdinal) {
    const std::size_t index = contacts.wx.size() == contacts.size() ? k : wallOrdinal;
    if (index >= contacts.wx.size() || index >= contacts.wy.size()) return {NAN, NAN};
    return {contacts.wx[index], contacts.wy[index]};
}

vtkSmartPointer<vtkUnstructuredGrid> particlesToVtk(const solver::Snapshot& s) {
    const auto& g = s.grains;
    const auto n = static_cast<vtkIdType>(g.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(n);
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType k = 0; k < n; ++k) {
        points->SetPoint(k, g.x[k], g.y[k], 0.0);
        vertices->InsertNextCell(1, &k);
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->SetCells(VTK_VERTEX, vertices);
    auto radius = floatArray("radius", 1, n);
    auto velocity = floatArray("velocity", 3, n);
    auto speed = floatArray("speed", 1, n);
    auto omega = floatArray("omega", 1, n);
    auto force = floatArray("force", 3, n);
    auto contactForce = floatArray("contact_force", 1, n);
    fill(radius, g.radius);
    fill(velocity, g.vx, 0);
    fill(velocity, g.vy, 1);
    fill(omega, g.omega);
    fill(force, g.fx, 0);
    fill(force, g.fy, 1);
    fill(contactForce, contactForcePerGrain(s));
    for (vtkIdType k = 0; k < n; ++k)
        speed->SetValue(
            k, std::hypot(velocity->GetTypedComponent(k, 0), velocity->GetTypedComponent(k, 1)));
    vtkPointData* pd = grid->GetPointData();
    for (vtkFloatArray* array :
         {radius.Get(), velocity.Get(), speed.Get(), omega.Get(), force.Get(), contactForce.Get()})
        pd->AddArray(array);
    if (g.hydro_fx.size() == g.size() && g.hydro_fy.size() == g.size()) {
        auto hydro = floatArray("hydro_force", 3, n);
        fill(hydro, g.hydro_fx, 0);
        fill(hydro, g.hydro_fy, 1);
        pd->AddArray(hydro);
    }
    pd->SetActiveScalars("radius");
    pd->SetActiveVectors("velocity");
    addSceneFieldData(s, grid->GetFieldData());
    return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> contactsToVtk(const solver::Snapshot& s) {
    const auto& c = s.contacts;
    const auto n = static_cast<vtkIdType>(c.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    vtkNew<vtkCellArray> lines;
    auto normal = floatArray("normal_force", 1, n);
    auto tangential = floatArray("tangential_force", 1, n);
    vtkNew<vtkIntArray> first, second;
    first->SetName("i");
    second->SetName("j");
    std::size_t wallOrdinal = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const auto a = static_cast<std::size_t>(c.i[k]);
        float bx, by;
        if (c.j[k] < 0) {
            std::tie(bx, by) = wallContactPoint(c, k, wallOrdinal++);
        } else {
            bx = s.grains.x[static_cast<std::size_t>(c.j[k])];
            by = s.grains.y[static_cast<std::size_t>(c.j[k])];
        }
        const vtkIdType ids[2] = {points->InsertNextPoint(s.grains.x[a], s.grains.y[a], 0.0),
                                  points->InsertNextPoint(bx, by, 0.0)};
        lines->InsertNextCell(2, ids);
        normal->SetValue(static_cast<vtkIdType>(k), c.normal_force[k]);
        tangential->SetValue(static_cast<vtkIdType>(k),
                             k < c.tangential_force.size() ? c.tangential_force[k] : 0.0f);
        first->InsertNextValue(c.i[k]);
        second->InsertNextValue(c.j[k]);
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->SetCells(VTK_LINE, lines);
    for (vtkDataArray* array :
         {static_cast<vtkDataArray*>(normal.Get()), static_cast<vtkDataArray*>(tangential.Get()),
          static_cast<vtkDataArray*>(first.Get()), static_cast<vtkDataArray*>(second.Get())})
        grid->GetCellData()->AddArray(array);
    grid->GetCellData()->SetActiveScalars("normal_force");
    addFieldValue(grid->GetFieldData(), "TimeValue", s.time_s);
    return grid;
}

vtkSmartPointer<vtkImageData> fluidToVtk(const solver::SnapshotFluid& f) {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(f.nx, f.ny, 1);
    image->SetOrigin(f.origin_x, f.origin_y, 0.0);
    image->SetSpacing(f.spacing_m, f.spacing_m, 1.0);
    const auto n = static_cast<vtkIdType>(f.nx) * f.ny;
    auto velocity = floatArray("velocity", 3, n);
    auto speed = floatArray("speed", 1, n);
    auto pressure = floatArray("pressure", 1, n);
    auto vorticity = floatArray("vorticity", 1, n);
    auto solid = floatArray("solid_fraction", 1, n);
    fill(velocity, f.ux, 0);
    fill(velocity, f.uy, 1);
    fill(pressure, f.pressure);
    fill(vorticity, f.vorticity);
    fill(solid, f.solid);
    for (vtkIdType k = 0; k < n; ++k)
        speed->SetValue(
            k, std::hypot(velocity->GetTypedComponent(k, 0), velocity->GetTypedComponent(k, 1)));
    vtkPointData* pd = image->GetPointData();
    for (vtkFloatArray* array :
         {velocity.Get(), speed.Get(), pressure.Get(), vorticity.Get(), solid.Get()})
        pd->AddArray(array);
    pd->SetActiveVectors("velocity");
    pd->SetActiveScalars("speed");
    return image;
}

vtkSmartPointer<vtkUnstructuredGrid> outlineToVtk(const solver::Snapshot& s) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    std::vector<vtkIdType> ids;
    for (const auto& [x, y] : s.outline)
        ids.push_back(points->InsertNextPoint(x, y, 0.0));
    vtkNew<vtkCellArray> cells;
    if (!ids.empty()) cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->SetCells(VTK_POLY_LINE, cells);
    addFieldValue(grid->GetFieldData(), "TimeValue", s.time_s);
    return grid;
}

namespace {

/// The contacts stored by contactsToVtk; wall points come back from each line's second point.
solver::SnapshotContacts contactsFromVtk(vtkUnstructuredGrid* contacts) {
    solver::SnapshotContacts c;
    vtkCellData* cd = contacts->GetCellData();
    c.normal_force = column(cd, "normal_force");
    c.tangential_force = column(cd, "tangential_force");
    for (const float v : column(cd, "i"))
        c.i.push_back(static_cast<std::int32_t>(v));
    for (const float v : column(cd, "j"))
        c.j.push_back(static_cast<std::int32_t>(v));
    c.wx.assign(c.i.size(), 0.0f);
    c.wy.assign(c.i.size(), 0.0f);
    for (vtkIdType k = 0;
         k < contacts->GetNumberOfCells() && k < static_cast<vtkIdType>(c.j.size()); ++k) {
        if (c.j[static_cast<std::size_t>(k)] >= 0) continue;
        double p[3];
        contacts->GetPoint(contacts->GetCell(k)->GetPointId(1), p);
        c.wx[static_cast<std::size_t>(k)] = static_cast<float>(p[0]);
        c.wy[static_cast<std::size_t>(k)] = static_cast<float>(p[1]);
    }
    return c;
}

/// The fluid grid stored by fluidToVtk.
solver::SnapshotFluid fluidFromVtk(vtkImageData* fluid) {
    solver::SnapshotFluid f;
    int dims[3];
    double origin[3], spacing[3];
    fluid->GetDimensions(dims);
    fluid->GetOrigin(origin);
    fluid->GetSpacing(spacing);
    f.nx = dims[0];
    f.ny = dims[1];
    f.origin_x = static_cast<float>(origin[0]);
    f.origin_y = static_cast<float>(origin[1]);
    f.spacing_m = static_cast<float>(spacing[0]);
    vtkPointData* fd = fluid->GetPointData();
    f.ux = column(fd, "velocity", 0);
    f.uy = column(fd, "velocity", 1);
    f.pressure = column(fd, "pressure");
    f.vorticity = column(fd, "vorticity");
    f.solid = column(fd, "solid_fraction");
    return f;
}

} // namespace

solver::Snapshot snapshotFromVtk(vtkUnstructuredGrid* particles, vtkUnstructuredGrid* contacts,
                                 vtkImageData* fluid, vtkUnstructuredGrid* outline) {
    solver::Snapshot s;
    readSceneFieldData(particles->GetFieldData(), s);
    auto& g = s.grains;
    for (vtkIdType k = 0; k < particles->GetNumberOfPoints(); ++k) {
        double p[3];
        particles->GetPoint(k, p);
        g.x.push_back(static_cast<float>(p[0]));
        g.y.push_back(static_cast<float>(p[1]));
    }
    vtkPointData* pd = particles->GetPointData();
    g.radius = column(pd, "radius");
    g.vx = column(pd, "velocity", 0);
    g.vy = column(pd, "velocity", 1);
    g.omega = column(pd, "omega");
    g.fx = column(pd, "force", 0);
    g.fy = column(pd, "force", 1);
    g.hydro_fx = column(pd, "hydro_force", 0);
    g.hydro_fy = column(pd, "hydro_force", 1);
    if (contacts) s.contacts = contactsFromVtk(contacts);
    if (fluid) s.fluid = fluidFromVtk(fluid);
    if (outline)
        for (vtkIdType k = 0; k < outline->GetNumberOfPoints(); ++k) {
            double p[3];
            outline->GetPoint(k, p);
            s.outline.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
        }
    return s;
}

} // namespace lbdem::vis
