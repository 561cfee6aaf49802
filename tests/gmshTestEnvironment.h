// Reparam - helpers for tests that run inside Gmsh (through its API)

#ifndef GMSH_TEST_ENVIRONMENT_H
#define GMSH_TEST_ENVIRONMENT_H

#include <string>
#include <vector>
#include "SPoint2.h"
#include "testPatches.h"

class GFace;
class MTriangle;
class MVertex;

// Gmsh's own triangles for a test triangulation (owned by the object)
struct gmshTriangulation {
  std::vector<MVertex *> vertices;
  std::vector<MTriangle *> triangles;
  explicit gmshTriangulation(const testTriangulation &t);
  ~gmshTriangulation();
};

// computeParametrization() with Mesh.CompoundParametrization = choice
struct gmshParametrization {
  bool ok = false;
  std::vector<MVertex *> nodes;
  std::vector<SPoint2> uv;
  std::vector<int> triangles;
};
gmshParametrization parametrizeWith(const std::vector<MTriangle *> &t,
                                    int choice);

// Largest |Q a_i - b_i| over the orthogonal Q (rotation or reflection) that
// best maps a onto b: the two maps differ only by the start and direction of
// the boundary on the circle
double distanceUpToOrthogonal(const std::vector<SPoint2> &a,
                              const std::vector<SPoint2> &b);

std::string tutorialFile(const std::string &name);

// A new discrete surface of the current Gmsh model with the triangulation's
// nodes (tagged from 1) and triangles; returns its tag
int addDiscreteSurface(const testTriangulation &t);

// The STL recipe on t in a cleared model: the automatic map, a uniform
// size, ClassifySurfaces{featureAngle (degrees), 1, 1, 180 deg},
// CreateGeometry, Mesh 2; returns the log. The size options are reset after.
std::vector<std::string> remeshWithRecipe(const testTriangulation &t,
                                          double size,
                                          double featureAngle = 40.);

// The surfaces of the current model without any element
std::vector<int> surfacesWithoutElements();

// The edges of the current model's surface triangles used by one triangle
// only (node tags, smaller first), and by more than two
std::vector<std::pair<std::size_t, std::size_t> >
freeMeshEdges(std::size_t *nonManifold = nullptr);

// A cleared model with the unit square as a discrete surface on a grid of
// 0.025, its bottom side cut by a model point 0.02 from the corner (a short
// curve, as the layout leaves between close corners), through
// CreateGeometry
void squareWithAShortCurve();

// Mesh.MeshSizeMin and Mesh.MeshSizeMax set to `size` while the object
// lives, then back to Gmsh's defaults (0 and 1e22), also when an assertion
// ends the test early
class uniformMeshSize {
public:
  explicit uniformMeshSize(double size);
  ~uniformMeshSize();
  uniformMeshSize(const uniformMeshSize &) = delete;
  uniformMeshSize &operator=(const uniformMeshSize &) = delete;
};

// squareWithAShortCurve() meshed (Mesh 2) at `size` with the current
// Mesh.Algorithm, the size options reset after; its face
GFace *meshedSquareWithAShortCurve(double size);

#endif
