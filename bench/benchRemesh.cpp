// Reparam - the whole STL recipe on one mesh, with one map and one planar
// mesher, and the quality and fidelity of the result.
//
//   reparamBenchRemesh file.stl map [algorithm [sizeFactor]]
//
// Merge, ClassifySurfaces{40 deg, 1, 1, 180 deg} and CreateGeometry with
// Mesh.CompoundParametrization = map, then Mesh 2 with Mesh.Algorithm =
// algorithm (default 6) at a uniform size of sizeFactor (default 1) times
// the input's mean edge length. Prints "classify S" (ClassifySurfaces)
// once the model is classified, then one line:
//
//   remesh map M algorithm A geometry S mesh S faces F meshed K triangles T
//   quadrangles Q inverted I hausdorff H mean D kappaMin K kappaMean K
//   below03 P etaMin E etaMean E tau T fidelity S fallbacks B
//   optimizedFaces O kappaMinBeforeOptimization K optimization S
//
// geometry: CreateGeometry (the parametrizations), mesh: Mesh 2; faces: the
// discrete faces (those whose parametrization failed too), meshed: those
// that got elements;
// inverted: elements (after Gmsh orients them) pointing against the input
// under them (meshFidelity::inverted), on the face's input, or on the inputs
// of the faces joined by cuts together (Mesh.CompoundOptimize moves
// triangles across them);
// hausdorff and mean: largest
// and element-weighted mean two-sided distance of a face to its input, in %
// of the input's bounding-box diagonal; kappa over all triangles, eta over
// all quadrangles, tau (%) over all edges; fallbacks: faces where the map
// (3 to 5) was not one-to-one and the mean value map took over;
// optimizedFaces: faces Mesh.CompoundOptimize ran on, the worst kappa
// before it and its seconds (within mesh).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <vector>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "OS.h"
#include "SBoundingBox3d.h"
#include "benchModel.h"
#include "gmsh.h"
#include "meshFidelity.h"
#include "faceQuality.h"
#include "reparamReport.h"
#include "reparamSurfaceMesh.h"

using namespace reparam;

namespace {

  // The elements of the triangle meshes of the faces pointing against
  // their inputs taken together (with REPARAM_BENCH_FACES, printed face by
  // face)
  std::size_t countInvertedTogether(const std::vector<GFace *> &faces)
  {
    std::vector<surfaceMesh> inputs, outputs;
    for(GFace *gf : faces) {
      inputs.push_back(inputTriangulationOf(gf));
      outputs.push_back(surfaceMeshOf(gf));
    }
    std::vector<int> elementFace;
    const surfaceMesh output = unionAsTriangles(outputs, nullptr, &elementFace);
    const std::vector<std::size_t> against =
      invertedElements(unionAsTriangles(inputs), output);
    if(std::getenv("REPARAM_BENCH_FACES")) {
      std::vector<std::size_t> perFace(faces.size(), 0);
      for(std::size_t e : against) perFace[elementFace[e]]++;
      for(std::size_t f = 0; f < faces.size(); f++)
        if(perFace[f])
          std::printf("face %d elements %lu inverted %lu input %lu\n",
                      faces[f]->tag(), faces[f]->getNumMeshElements(),
                      perFace[f], faces[f]->stl_triangles.size() / 3);
    }
    return against.size();
  }

  // Each face against its own input, but the faces optimized together
  // across their curves (Mesh.CompoundOptimize moves triangles across them,
  // Geo/optimize/reparamOptimizeAcrossCuts.h) against their inputs together
  std::size_t countInvertedElements(const std::vector<GFace *> &faces)
  {
    std::set<GFace *> grouped;
    std::map<int, std::vector<GFace *> > groups;
    for(GFace *gf : faces) {
      const optimizationRecord *o = findOptimization(gf);
      if(o && o->acrossCuts) groups[o->group].push_back(gf);
    }
    std::size_t inverted = 0;
    for(const auto &g : groups) {
      grouped.insert(g.second.begin(), g.second.end());
      inverted += countInvertedTogether(g.second);
    }
    for(GFace *gf : faces) {
      if(grouped.count(gf)) continue;
      const std::size_t n =
        countInverted(inputTriangulationOf(gf), surfaceMeshOf(gf));
      if(n && std::getenv("REPARAM_BENCH_FACES"))
        std::printf("face %d elements %lu inverted %lu input %lu\n", gf->tag(),
                    gf->getNumMeshElements(), n, gf->stl_triangles.size() / 3);
      inverted += n;
    }
    return inverted;
  }

} // namespace

int main(int argc, char **argv)
{
  if(argc < 3) {
    std::fprintf(stderr, "usage: %s file.stl map [algorithm [sizeFactor]]\n",
                 argv[0]);
    return 2;
  }
  const int map = std::atoi(argv[2]);
  const int algorithm = argc > 3 ? std::atoi(argv[3]) : 6;
  const double sizeFactor = argc > 4 ? std::atof(argv[4]) : 1.;

  classifiedStl stl = loadClassifiedStl(argv[1], map);
  // before the rest, so that a caller that times out knows which stage hung
  std::printf("classify %.3f\n", stl.classifySeconds);
  std::fflush(stdout);
  double t0 = TimeOfDay();
  try {
    gmsh::model::mesh::createGeometry();
  } catch(...) {
  }
  double geometry = TimeOfDay() - t0;

  const double size = sizeFactor * stl.meanEdge;
  gmsh::option::setNumber("Mesh.MeshSizeMin", size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::option::setNumber("Mesh.Algorithm", algorithm);
  // Mesh 2 times the meshing alone (quality and fidelity are measured
  // below), unless REPARAM_BENCH_REPORT is set: then it includes Reparam's
  // report, to measure what that costs
  gmsh::option::setNumber("Mesh.CompoundReport",
                          std::getenv("REPARAM_BENCH_REPORT") ? 1 : 0);
  t0 = TimeOfDay();
  try {
    gmsh::model::mesh::generate(2);
  } catch(...) {
  }
  double mesh = TimeOfDay() - t0;

  t0 = TimeOfDay();
  SBoundingBox3d box;
  std::vector<GFace *> meshedFaces;
  std::size_t faces = 0, meshed = 0, inverted = 0, fallbacks = 0;
  std::size_t optimized = 0;
  double kappaMinBeforeOptimization = 1., optimization = 0.;
  double hausdorff = 0., weightedMean = 0.;
  std::size_t weight = 0;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it) {
    GFace *gf = *it;
    if(gf->stl_triangles.empty()) continue;
    faces++;
    // a map chosen by hand that is not one-to-one falls back to mean value
    const parametrizationRecord *p = findParametrization(gf);
    if(p && map != 6 && p->map != map) fallbacks++;
    for(const SPoint3 &p : gf->stl_vertices_xyz) box += p;
    if(gf->triangles.empty() && gf->quadrangles.empty()) continue;
    meshed++;
    meshedFaces.push_back(gf);
    if(const optimizationRecord *o = findOptimization(gf)) {
      optimized++;
      kappaMinBeforeOptimization =
        std::min(kappaMinBeforeOptimization, o->kappaMinBefore);
      optimization += o->seconds;
    }
    // the distances face by face, the orientation below on the whole input
    const std::size_t none = 0;
    meshFidelity f =
      compareToInput(inputTriangulationOf(gf), surfaceMeshOf(gf), &none);
    hausdorff = std::max(hausdorff, f.hausdorff);
    weightedMean += f.meanDistance * f.elements;
    weight += f.elements;
  }
  inverted = countInvertedElements(meshedFaces);
  // faces whose CreateGeometry failed: not meshed, holes in the mesh
  faces += unparametrizedFaces(GModel::current()).size();
  double diagonal = box.empty() ? 1. : box.diag();
  faceQuality q = computeFaceQuality(meshedFaces);
  double fidelity = TimeOfDay() - t0;

  std::printf("remesh map %d algorithm %d geometry %.3f mesh %.3f faces %lu "
              "meshed %lu triangles %lu quadrangles %lu inverted %lu "
              "hausdorff %.4g mean %.4g kappaMin %.4f kappaMean %.4f below03 "
              "%.4f etaMin %.4f etaMean %.4f tau %.2f fidelity %.3f "
              "fallbacks %lu optimizedFaces %lu kappaMinBeforeOptimization "
              "%.4f optimization %.3f\n",
              map, algorithm, geometry, mesh, faces, meshed, q.triangles,
              q.quadrangles, inverted, 100. * hausdorff / diagonal,
              weight ? 100. * weightedMean / weight / diagonal : 0., q.kappaMin,
              q.kappaMean, q.kappaShareBelow03, q.etaMin, q.etaMean, q.tau,
              fidelity, fallbacks, optimized,
              optimized ? kappaMinBeforeOptimization : q.kappaMin,
              optimization);
  gmsh::finalize();
  return 0;
}
