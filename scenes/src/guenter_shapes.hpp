#pragma once
// The parametric objects of the guenter scene (a sphere, a torus, a rounded
// cube and a vase), tessellated, and the winding their outside shows.
#include "gpu_mesh.hpp"

namespace foveate::detail {

constexpr int kGuenterShapes = 4;

/// Shape `shape` (0 sphere, 1 torus, 2 rounded cube, 3 vase) on a `seg` x
/// `seg` parameter grid (2 seg^2 triangles), with outward normals.
MeshData guenter_shape(int shape, int seg);

/// Two triangles per cell of a `cells` x `cells` grid whose (cells + 1)^2
/// vertices `m` holds row by row, each wound a, c, b (a cell's corners a, b
/// along the row, c, d on the next).
void grid_triangles(MeshData& m, int cells);

/// The winding on the screen of the shape's outside (GpuMesh::outside): the
/// sphere and the rounded cube turn clockwise, the torus, whose tube runs the
/// other way round, counter-clockwise; the vase is open at both ends
/// (unknown: both sides drawn).
GpuMesh::Winding guenter_shape_outside(int shape);

}  // namespace foveate::detail
