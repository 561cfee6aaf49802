// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Mesh.CompoundCurvatureMetric = N: the sizes of the discrete faces Reparam
// parametrized from the curvature of their input (Mesh/sizes/curvatureMetric.h),
// through Gmsh's size functions (hook in BackgroundMeshTools.cpp,
// patches/0016): BAMG (Mesh.Algorithm = 7) meshes with the anisotropic
// metric, pulled back to the (u, v) plane by the map's Jacobian; the
// isotropic meshers take its smallest size; a curve takes the size along
// it in the faces it bounds. The sizes are bounded by Mesh.MeshSizeMin and
// Mesh.MeshSizeMax. The triangles of a face meshed by BAMG with the metric
// are elongated on purpose: Mesh.CompoundOptimize, which raises their
// kappa, leaves them.

#ifndef REPARAM_CURVATURE_METRIC_H
#define REPARAM_CURVATURE_METRIC_H

class GEntity;
class GFace;
class SMetric3;

namespace reparam {

// The metric at (x, y, z) on ge, a discrete face Reparam parametrized;
// false elsewhere or with the option off
bool reparamCurvatureMetric(GEntity *ge, double u, double x, double y, double z,
                            SMetric3 &metric);

// Whether gf is meshed by BAMG with the curvature metric
bool reparamAnisotropicFace(const GFace *gf);

// Around the planar mesher of such a face (Geo/planar/reparamFaceMeshing.cpp): the
// metric is graded on the input (by 1.3), and BAMG's own
// grading, in the (u, v) plane, is off meanwhile
void reparamBeginAnisotropicMeshing(GFace *gf);
void reparamEndAnisotropicMeshing();

} // namespace reparam

#endif
