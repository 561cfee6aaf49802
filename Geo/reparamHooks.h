// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Every function Gmsh calls into Reparam, in the order of the pipeline, each
// documented once. The patches of patches/ add only these calls (and the
// options' table entries) to Gmsh's files, which include this header; the
// functions are defined in the Geo/ room of their stage, which translate
// Gmsh's objects and call the stage's entry function in Mesh/. Outside
// namespace reparam: Gmsh's files call them by these names.
//
// Threads: Gmsh meshes the faces of a model in parallel with
// General.NumThreads > 1 (an OpenMP loop in Mesh/Generator.cpp); the face
// hooks (Mesh2D) may then run on several threads at once, each for its own
// face; every other hook runs on Gmsh's main thread. What Reparam keeps
// between the hooks, and which thread touches what: Geo/core/reparamState.h.

#ifndef REPARAM_HOOKS_H
#define REPARAM_HOOKS_H

#include <cstddef>
#include <functional>
#include <string>
#include <vector>
#include "SBoundingBox3d.h"
#include "SPoint2.h"
#include "SPoint3.h"

class Fl_Widget;
class GEdge;
class GEntity;
class GFace;
class GModel;
class MElement;
class MElementOctree;
class MLine;
class MTriangle;
class MVertex;
class SMetric3;
class optionWindow;
class reparamUvLocator;

// --- Options (Mesh.Compound*; patches/0002, Common/DefaultOptions.h) -------
// Their values live in Reparam (Geo/options/reparamOptions.cpp) so that
// Gmsh's Common/Context.h stays untouched; the accessors follow Gmsh's
// opt_* convention (Common/Options.h: OPT_ARGS_NUM, OPT_ARGS_STR)
double opt_mesh_compound_parametrization(int num, int action, double val);
double opt_mesh_compound_curvature_metric(int num, int action, double val);
double opt_mesh_compound_curve_corners(int num, int action, double val);
double opt_mesh_compound_fill_holes(int num, int action, double val);
double opt_mesh_compound_repair(int num, int action, double val);
double opt_mesh_compound_layout(int num, int action, double val);
double opt_mesh_compound_noise_size(int num, int action, double val);
double opt_mesh_compound_feature_scale(int num, int action, double val);
double opt_mesh_compound_optimize(int num, int action, double val);
double opt_mesh_compound_mesh_size_gradient(int num, int action, double val);
double opt_mesh_compound_mesh_size_from_strips(int num, int action,
                                               double val);
double opt_mesh_compound_report(int num, int action, double val);
double opt_mesh_compound_split(int num, int action, double val);
std::string opt_mesh_compound_report_file(int num, int action,
                                          const std::string &val);

// The Compound tab of Tools > Options > Mesh, whose widgets set the options
// above (patches/0017, Fltk/optionWindow.cpp; Geo/options)
void reparamAddCompoundTab(optionWindow *o, int x, int y, int w, int h,
                           int bw, void (*changed)(Fl_Widget *, void *));
void reparamApplyCompoundTab(optionWindow *o);

// --- Input: reading an STL file (patches/0009, Geo/GModelIO_STL.cpp;
// Geo/input) ---------------------------------------------------------------
// The facets of a file cut short that are complete, given the count the
// file announces and the bytes read
unsigned int reparamCompleteStlFacets(unsigned int facets,
                                      std::size_t bytesRead);
// Facets with a NaN or infinite coordinate dropped (bbox recomputed);
// returns how many
std::size_t
reparamDropInvalidStlFacets(std::vector<std::vector<SPoint3> > &points,
                            SBoundingBox3d &bbox);
// Facets turned to agree with their neighbours, repeated ones dropped;
// returns how many were turned
std::size_t reparamOrientStlFacets(std::vector<std::vector<SPoint3> > &points);

// --- Layout: ClassifySurfaces{..., forParametrization = 1} (patches/0006,
// 0012, Geo/GModelParametrize.cpp; Geo/layout) -------------------------------
// Reparam's patch layout of the classified triangles (Mesh.CompoundLayout):
// noise patches merged, every patch cut until its map is one-to-one; the
// cuts' segments added to `lines`. 0: Gmsh's own split loop runs. Either
// way the last layout's record and gm's start anew (Geo/core/reparamState.h)
int reparamLayoutPatches(GModel *gm, std::vector<MLine *> &lines);
// Whether a node where three cut edges or more of the layout meet ends the
// curves through it
bool reparamBreakCurveAt(MVertex *v);
// Gmsh's own split loop (Mesh.CompoundLayout = 0): whether it can keep a
// patch (1), should split it in 2 (2, the reason in `why`), or leaves the
// question to Gmsh's own test (0)
int reparamCheckParametrizable(const std::vector<MTriangle *> &triangles,
                               std::string &why);

// --- Parametrization: CreateGeometry, Compound Surface (patches/0001,
// 0011, 0019, Geo/discreteFace.cpp, Geo/GModelParametrize.cpp;
// Geo/parametrize) ----------------------------------------------------------
// The start of gf's CreateGeometry: its record starts anew (what its earlier
// geometry and meshes left goes; Geo/core/reparamState.h)
void reparamBeginFaceGeometry(GFace *gf);
// Whether Reparam's maps take gf although its input has triangles of gamma
// down to minGamma (an Info, no Gmsh warning); false with Gmsh's own map
bool reparamTakesPoorInput(GFace *gf, double minGamma);
// gf's parametrization by the map of Mesh.CompoundParametrization, written
// in Gmsh's arrays: 1 done, -1 failed (reported; the safety net then keeps
// the input, reparamKeepInputMesh), 0 left to Gmsh's own map
int reparamComputeFaceParametrization(GFace *gf,
                                      const std::vector<MTriangle *> &triangles,
                                      std::vector<MVertex *> &nodes,
                                      std::vector<SPoint2> &stl_vertices_uv,
                                      std::vector<SPoint3> &stl_vertices_xyz,
                                      std::vector<int> &stl_triangles);
// The same for triangles of no face (Gmsh's computeParametrization, called
// by its own split test): a failure is an error
int reparamComputeParametrization(const std::vector<MTriangle *> &triangles,
                                  std::vector<MVertex *> &nodes,
                                  std::vector<SPoint2> &stl_vertices_uv,
                                  std::vector<SPoint3> &stl_vertices_xyz,
                                  std::vector<int> &stl_triangles);
// gf's parametrization failed: keeps its input triangles for its mesh, with
// one warning naming it and the reason; false with Gmsh's own map
bool reparamKeepInputMesh(GFace *gf);

// Before the faces are meshed (patches/0024, Mesh/Generator.cpp): the map
// of every discrete face whose map options (Mesh.CompoundParametrization,
// FillHoles, Repair) changed since its CreateGeometry computed again, in
// its arrays (Geo/parametrize/reparamParametrizeAgain.h); a change of the
// options only ClassifySurfaces reads named once
void reparamParametrizeAgain(GModel *m);
// At the start of gf's mesh (Geo/discreteFace.cpp): true once after its
// (u, v) were computed again, when it makes its parametric triangles anew
bool reparamTakeNewParametrization(GFace *gf);

// The (u, v) triangles of a face, found by Reparam's tree where the image
// is not convex (patches/0007, 0021, Geo/discreteFace.cpp;
// Geo/parametrize/reparamUvLocate.cpp)
MTriangle *reparamClosestUvTriangle(const std::vector<MTriangle> &t2d,
                                    double &u, double &v);
// A locator built with gf's parametrization (null with Gmsh's own map)
reparamUvLocator *reparamNewUvLocator(const std::vector<MTriangle> &t2d);
void reparamDeleteUvLocator(reparamUvLocator *locator);
// The triangle holding (u, v), by the locator (else Gmsh's octree)
MElement *reparamFindUvTriangle(const reparamUvLocator *locator,
                                const MElementOctree *octree,
                                const std::vector<MTriangle> &t2d, double u,
                                double v);
// parFromPoint's answer for p, remembered by the locator (f computes it)
SPoint2 reparamParFromPoint(const reparamUvLocator *locator, const SPoint3 &p,
                            const std::function<SPoint2(const SPoint3 &)> &f);

// --- Curves: the 1D mesh (patches/0010, 0014, 0020, Mesh/meshGEdge.cpp,
// Mesh/Generator.cpp, Mesh/meshGFace.cpp; Geo/curves, Geo/sizes) -----------
// The nodes of a discrete curve moved onto the corners of the input
// polyline (Mesh.CompoundCurveCorners)
void reparamSnapCurveMesh(GEdge *ge, std::vector<MVertex *> &nodes);
// Around Mesh1D: the sizes along the discrete curves graded from the ends
// of the short ones (Mesh.CompoundMeshSizeGradient)
void reparamBeginCurveSizeGrading(GModel *m);
void reparamEndCurveSizeGrading(GModel *m);
// Around the split of curve segments in Mesh2D, which faces meshed on other
// threads read: waits until no face is being meshed
void reparamBeginCurveSplit();
void reparamEndCurveSplit();

// --- Sizes (patches/0014, 0016, Mesh/BackgroundMeshTools.cpp;
// Geo/sizes) ----------------------------------------------------------------
// The size at (x, y, z) on ge, graded from its curves' short segments
// (Mesh.CompoundMeshSizeGradient); `size` where there is no grading
double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size);
// The smallest size from the curvature of ge's input
// (Mesh.CompoundCurvatureMetric; 1e22 where there is none), and the metric
// intersected with those sizes
double reparamCurvatureMeshSize(GEntity *ge, double u, double x, double y,
                                double z);
void reparamIntersectCurvatureMetric(GEntity *ge, double u, double x,
                                     double y, double z, SMetric3 &metric);

// --- Planar mesh of a face (patches/0004, 0008, 0013, 0014, 0015, 0018,
// 0022, 0023, Geo/discreteFace.cpp, Mesh/meshGFace.cpp, Mesh/Generator.cpp,
// Mesh/meshGFaceOptimize.cpp, Mesh/meshGFaceBamg.cpp; Geo/planar) -----------
// Whether the faces of m may be meshed in parallel (not under BAMG)
bool reparamMeshInParallel(GModel *m, int dim);
// Around a discrete face's planar mesh: its sizes and crease curves set up,
// then taken down (in the context of the thread meshing it)
void reparamBeginFaceMeshing(GFace *gf);
void reparamEndFaceMeshing(GFace *gf);
// A face kept as its input triangles (reparamKeepInputMesh) meshed with
// them, stitched to its curves' nodes; false for other faces
bool reparamMeshFromInput(GFace *gf);
// After a Delaunay-based mesher: gf's mesh repaired, and kept when the few
// elements Gmsh's test rejects cross folds thinner than the mesh size
bool reparamKeepPlanarMesh(GFace *gf);
// Gmsh's planar mesher cannot recover a segment of ge in gf's (u, v)
// plane: true when Reparam meshes gf with its input triangles instead
// (reparamEndFaceMeshing), Gmsh's error then not given
bool reparamLostCurveSegment(GFace *gf, GEdge *ge);
// Whether gf's mesh leaves a segment of its curves unused (a hole)
bool reparamPlanarMeshLeavesHole(GFace *gf);
// After MeshAdapt: gf's mesh compared with the other meshers' where it
// leaves a hole or elements against the input
bool reparamCheckMeshAdaptMesh(GFace *gf);
// BAMG: the most vertices it may make for gf (-1.1e100: its default), and
// whether gf keeps its Delaunay mesh when BAMG fails
double reparamBamgMaxVertices(GFace *gf, int vertices);
bool reparamBamgFailed(GFace *gf);
// Whether the recombination of gf smooths in its (one-to-one) (u, v) plane
bool reparamRecombineWithParametrization(GFace *gf);
// gf's mesh oriented along its input, element by element; false leaves it
// to Gmsh's own orientation
bool reparamOrientMeshedFace(GFace *gf);

// --- Optimization on the input (patches/0013, Geo/discreteFace.cpp,
// Mesh/Generator.cpp; Geo/optimize, Geo/quad) --------------------------------
// gf's new mesh optimized on its input (Mesh.CompoundOptimize)
bool reparamOptimizeMeshedFace(GFace *gf);
// Once every face is meshed: the faces a patch was cut into optimized
// together across their cuts, quadrangles squared up, curve nodes slid
int reparamOptimizeMeshedModel(GModel *m);

// --- Report (patches/0001, 0005, Geo/discreteFace.cpp,
// Mesh/Generator.cpp; Geo/report) -------------------------------------------
// gf's new mesh measured (meshed in `seconds`) for the model's report
void reparamReportMeshedFace(GFace *gf, double seconds);
// The report printed (Mesh.CompoundReport) and written
// (Mesh.CompoundReportFile) once the model is meshed and oriented; the face
// reports gathered since the last one go
void reparamReportMeshedModel(GModel *m);

#endif
