// Conversions between a Snapshot and the VTK data sets that are written to disk and drawn.
#pragma once

#include "solver/scene/Snapshot.h"

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkUnstructuredGrid;

namespace lbdem::vis {

/// Grain centres as vertex cells; point arrays radius, velocity, speed, omega, force,
/// hydro_force (wet scenes) and contact_force (sum of the grain's normal contact forces); field
/// data carries the time, step, tau_c, domain, slope, walls, case name and metrics, so a run can
/// be re-rendered from its files alone.
vtkSmartPointer<vtkUnstructuredGrid> particlesToVtk(const solver::Snapshot& snapshot);
/// One line per contact between the two centres (wall contacts: centre to wall point); cell
/// arrays normal_force, tangential_force, i and j (j = -1 for a wall).
vtkSmartPointer<vtkUnstructuredGrid> contactsToVtk(const solver::Snapshot& snapshot);
/// The fluid grid with point arrays velocity (3 components, z = 0), speed, pressure, vorticity
/// and solid_fraction.
vtkSmartPointer<vtkImageData> fluidToVtk(const solver::SnapshotFluid& fluid);
/// The flow-front outline as one polyline cell (no cell when the outline is empty).
vtkSmartPointer<vtkUnstructuredGrid> outlineToVtk(const solver::Snapshot& snapshot);

/// Rebuilds a Snapshot from data sets written by the functions above; contacts, fluid and
/// outline may be null (dry scene, series absent). Metrics come back from field data.
solver::Snapshot snapshotFromVtk(vtkUnstructuredGrid* particles, vtkUnstructuredGrid* contacts,
                                 vtkImageData* fluid, vtkUnstructuredGrid* outline);

/// The wall point of contact k: (wx[k], wy[k]) when the arrays have one entry per contact, or the
/// n-th entry (n = number of wall contacts before k) when they hold wall contacts only.
std::pair<float, float> wallContactPoint(const solver::SnapshotContacts& contacts, std::size_t k,
                                         std::size_t wallOrdinal);

} // namespace lbdem::vis
