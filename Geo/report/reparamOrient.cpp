// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Orientation of the new mesh of a discrete face (called from
// orientMeshGFace, patches/0004, which declares it too).
//
// Orientation of the new mesh of a discrete face (hook in orientMeshGFace,
// patches/0004). Gmsh orients a face's mesh from its first element alone,
// by the normal of the input triangle under one of its nodes: one crease or
// one sliver of the input there, or a first element with no interior node
// whose centroid falls outside a non-convex (u, v) image, and the whole face
// comes out reversed (skull: 715 of 715 triangles of one face). Every
// element votes here, against the input under it (meshFidelity::inverted).

#include <cstdio>
#include "GFace.h"
#include "GmshMessage.h"
#include "MElement.h"
#include "meshFidelity.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSurfaceMesh.h"

using namespace reparam;

bool reparamOrientMeshedFace(GFace *gf)
{
  // a face kept as its input triangles has the input's orientation, and no
  // (u, v) for Gmsh's test to look at
  if(keptAsInput(gf)) return true;
  // Gmsh's own map keeps Gmsh's own orientation: it is the reference
  if(getReparamOptions().parametrization ==
       (int)compoundParametrization::gmsh ||
     gf->geomType() != GEntity::DiscreteSurface || gf->stl_triangles.empty())
    return false;
  const std::size_t elements = gf->getNumMeshElements();
  // The report (Mesh.CompoundReport) has already searched the input under
  // every element of this mesh; used once, so that a later call (after the
  // elements were edited) counts again
  faceReport *report = findFaceReport(gf);
  if(report && report->oriented) report = nullptr;
  // else the optimizer's count (once): on all the inputs of the faces it
  // worked on together (a triangle across a crossed cut lies over its
  // neighbour's input too: on gf's own input alone it may seem against)
  std::size_t inverted = 0;
  const bool counted = takeOptimizationCount(gf, inverted);
  if(report && report->hasInput)
    inverted = report->fidelity.inverted;
  else if(!counted)
    inverted = countInverted(inputTriangulationOf(gf), surfaceMeshOf(gf));
  if(2 * inverted > elements) {
    for(std::size_t i = 0; i < elements; i++) gf->getMeshElement(i)->reverse();
    inverted = elements - inverted;
  }
  if(report && report->hasInput) {
    report->fidelity.inverted = inverted;
    report->oriented = true;
  }
  if(inverted) {
    // where, so that the user can look (a second search, only then)
    const surfaceMesh mesh = surfaceMeshOf(gf);
    const std::vector<std::size_t> against =
      invertedElements(inputTriangulationOf(gf), mesh);
    char where[96] = "";
    if(!against.empty() && against[0] < mesh.triangles.size()) {
      SPoint3 at(0., 0., 0.);
      for(int n : mesh.triangles[against[0]]) at += mesh.points[n];
      at *= 1. / 3.;
      snprintf(where, sizeof(where), " (one at (%g, %g, %g))", at.x(), at.y(),
               at.z());
    }
    Msg::Warning("Reparam: surface %d: %lu of its %lu elements point against "
                 "the input normals%s",
                 gf->tag(), inverted, elements, where);
  }
  return true;
}

