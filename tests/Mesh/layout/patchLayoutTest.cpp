// Reparam - the patch layout of ClassifySurfaces: noise merged, parts cut
// until verified, every part a disk the automatic map flattens one-to-one,
// and the layout always ends

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GModel.h"
#include "MTriangle.h"
#include "bijectivityCheck.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "patchLayout.h"
#include "reparamLayout.h"
#include "reparamParametrize.h"
#include "reparamTrianglePatch.h"
#include "triangleAdjacency.h"

using namespace reparam;

namespace {

  layoutMesh meshOf(const testTriangulation &t)
  {
    layoutMesh m;
    m.points = t.points;
    m.triangles = t.triangles;
    return m;
  }

  // The layout with Reparam's own verification (the automatic map on
  // Gmsh's triangles), counting the parts it verified
  layoutResult layoutWithMaps(const layoutMesh &mesh,
                              const layoutParameters &parameters,
                              int *verified = nullptr)
  {
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    testTriangulation t{mesh.points, mesh.triangles};
    gmshTriangulation g(t);
    std::atomic<int> calls(0); // on several threads with parameters.threads
    partVerifier verify = [&](const std::vector<int> &part) {
      calls++;
      std::vector<MTriangle *> tris;
      for(int i : part) tris.push_back(g.triangles[i]);
      return reparamVerifyPart(tris);
    };
    layoutResult r = computePatchLayout(mesh, parameters, verify);
    if(verified) *verified = calls;
    return r;
  }

  // Every triangle in a patch, and every patch a disk (holes allowed):
  // makeDiscretePatch accepts it as it is
  void expectDiskPatches(const layoutMesh &mesh, const layoutResult &r)
  {
    std::vector<std::vector<int> > parts(r.numPatches);
    for(std::size_t t = 0; t < r.patch.size(); t++) {
      ASSERT_GE(r.patch[t], 0);
      ASSERT_LT(r.patch[t], r.numPatches);
      parts[r.patch[t]].push_back((int)t);
    }
    for(const auto &part : parts) {
      ASSERT_FALSE(part.empty());
      std::map<int, int> local;
      std::vector<SPoint3> points;
      std::vector<std::array<int, 3> > tris;
      for(int t : part) {
        std::array<int, 3> tri;
        for(int k = 0; k < 3; k++) {
          auto it = local.insert(
            std::make_pair(mesh.triangles[t][k], (int)points.size()));
          if(it.second) points.push_back(mesh.points[mesh.triangles[t][k]]);
          tri[k] = it.first->second;
        }
        tris.push_back(tri);
      }
      discretePatch patch;
      reparamError err = makeDiscretePatch(points, tris, patch);
      EXPECT_TRUE(err.ok())
        << err.what() << " (" << part.size() << " triangles)";
    }
    EXPECT_TRUE(r.unverified.empty());
  }

  // rectangleGrid(n, n) without the cells (i, j) listed
  testTriangulation gridWithout(int n,
                                const std::vector<std::array<int, 2> > &cells)
  {
    testTriangulation t = rectangleGrid(n, n, 1., 1.);
    std::vector<std::array<int, 3> > kept;
    for(std::size_t k = 0; k < t.triangles.size(); k++) {
      int cell = (int)k / 2, i = cell % n, j = cell / n;
      if(std::find(cells.begin(), cells.end(), std::array<int, 2>{i, j}) ==
         cells.end())
        kept.push_back(t.triangles[k]);
    }
    t.triangles = kept;
    return t;
  }

  std::vector<std::array<int, 2> > edgesOf(const std::array<int, 3> &t)
  {
    return {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}};
  }

  // Length of the cut between the sides of a bisection of the whole mesh,
  // and each side's area
  double cutOf(const layoutMesh &mesh, const triangleAdjacency &adjacency,
               const std::vector<char> &side, double area[2])
  {
    area[0] = area[1] = 0.;
    for(std::size_t t = 0; t < side.size(); t++)
      area[(int)side[t]] += triangleArea(mesh, (int)t);
    double cut = 0.;
    for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
      if(adjacency.numTriangles((int)e) != 2) continue;
      const int *tris = &adjacency.edgeTriangles[adjacency.edgeStart[e]];
      if(side[tris[0]] != side[tris[1]])
        cut += edgeLength(mesh, adjacency.edges[e]);
    }
    return cut;
  }

} // namespace

TEST(patchLayout, noisePatchIsMergedAndItsPinchGoesWithIt)
{
  // rectangleGrid's cell (1, 0) is cut (odd) into (a, b, d) and (a, d, c):
  // the second touches the boundary at node a = (1, 0) only, so as a
  // patch of its own it pinches the patch around it there
  layoutMesh mesh = meshOf(rectangleGrid(8, 8, 1., 1.));
  const std::array<int, 3> spike = mesh.triangles[2 * 1 + 1];
  ASSERT_EQ(spike[0], 1); // node (1, 0)
  mesh.featureEdges = edgesOf(spike);
  layoutParameters p;
  p.noiseTriangles = 1;
  layoutResult r = layoutWithMaps(mesh, p);
  EXPECT_EQ(r.featurePatches, 2);
  EXPECT_EQ(r.mergedNoise, 1);
  EXPECT_EQ(r.cleanedPatches, 1);
  EXPECT_EQ(r.numPatches, 1);
  EXPECT_TRUE(r.splits.empty());
  // the spike's sharp edges are no longer cuts: only the grid's boundary
  EXPECT_EQ(r.cutEdges.size(), 4u * 8u);
  expectDiskPatches(mesh, r);

  // Kept as a patch, it leaves the big one pinched: that one is parted
  // between its two fans at the pinch, before any map
  p.noiseTriangles = 0;
  int verified = 0;
  r = layoutWithMaps(mesh, p, &verified);
  EXPECT_EQ(r.mergedNoise, 0);
  EXPECT_EQ(r.numPatches, 3);
  ASSERT_EQ(r.splits.size(), 1u);
  EXPECT_EQ(r.splits[0].reason, "its boundary touches itself at a node");
  EXPECT_EQ(verified, 3); // the spike and the two parts
  expectDiskPatches(mesh, r);
}

namespace {

  // A surface without sharp edges that must be cut: into disks, at least
  // two, and a few (at most maxPatches, after at most twice as many
  // verifications), not crumbled triangle by triangle
  void expectCutIntoFewDisks(const testTriangulation &t, int maxPatches)
  {
    layoutMesh mesh = meshOf(t);
    int verified = 0;
    layoutResult r = layoutWithMaps(mesh, layoutParameters(), &verified);
    EXPECT_EQ(r.featurePatches, 1);
    EXPECT_GE(r.numPatches, 2);
    EXPECT_LE(r.numPatches, maxPatches);
    EXPECT_LE(verified, 2 * maxPatches);
    expectDiskPatches(mesh, r);
  }

} // namespace

TEST(patchLayout, pinchedAnnulusIsCutIntoDisks)
{
  // A hole whose corner (1, 1) is also a corner of the outer boundary
  expectCutIntoFewDisks(
    gridWithout(6, {{0, 0}, {1, 1}, {1, 2}, {2, 1}, {2, 2}}), 4);
}

TEST(patchLayout, closedSurfacesAreCutIntoDisks)
{
  expectCutIntoFewDisks(sphere(24, 12), 8);
  expectCutIntoFewDisks(torus(32, 12, 2., 0.6), 8);
}

TEST(patchLayout, twoThreadsGiveTheSameLayout)
{
  // parts verified on two threads at once (General.NumThreads = 2): the
  // same patches, numbered alike, and the same splits in the same order
  for(const testTriangulation &t :
      {sphere(24, 12), torus(32, 12, 2., 0.6), hemisphere(12, 48)}) {
    layoutMesh mesh = meshOf(t);
    layoutParameters one, two;
    two.threads = 2;
    int verifiedOne = 0, verifiedTwo = 0;
    const layoutResult a = layoutWithMaps(mesh, one, &verifiedOne);
    const layoutResult b = layoutWithMaps(mesh, two, &verifiedTwo);
    EXPECT_EQ(a.patch, b.patch);
    EXPECT_EQ(a.numPatches, b.numPatches);
    EXPECT_EQ(verifiedOne, verifiedTwo);
    ASSERT_EQ(a.splits.size(), b.splits.size());
    for(std::size_t i = 0; i < a.splits.size(); i++) {
      EXPECT_EQ(a.splits[i].triangles, b.splits[i].triangles);
      EXPECT_EQ(a.splits[i].depth, b.splits[i].depth);
      EXPECT_EQ(a.splits[i].reason, b.splits[i].reason);
    }
    EXPECT_EQ(a.cutEdges, b.cutEdges);
  }
  // the sphere and the torus are cut
  EXPECT_GE(
    layoutWithMaps(meshOf(sphere(24, 12)), layoutParameters()).numPatches, 2);
}

TEST(patchLayout, twoTriangleClosedPiecesEnd)
{
  // pelvis_tlem2's pattern, on which Gmsh's split loop never ends: pieces
  // of two triangles on the same three nodes, facing opposite ways
  testTriangulation t = rectangleGrid(4, 4, 1., 1.);
  layoutMesh mesh = meshOf(t);
  const int pieces = 5;
  for(int k = 0; k < pieces; k++) {
    int n = (int)mesh.points.size();
    mesh.points.push_back(SPoint3(2. + k, 0., 0.));
    mesh.points.push_back(SPoint3(2.5 + k, 0., 0.));
    mesh.points.push_back(SPoint3(2. + k, 0.5, 0.));
    mesh.triangles.push_back({n, n + 1, n + 2});
    mesh.triangles.push_back({n, n + 2, n + 1});
    for(auto e : edgesOf({n, n + 1, n + 2})) mesh.featureEdges.push_back(e);
  }
  layoutParameters p;
  p.noiseTriangles = 2;
  layoutResult r = layoutWithMaps(mesh, p);
  EXPECT_EQ(r.numPatches, 1 + 2 * pieces);
  expectDiskPatches(mesh, r);
}

TEST(patchLayout, bisectionCutsAStripStraightAcross)
{
  layoutMesh mesh = meshOf(rectangleGrid(40, 4, 10., 1.));
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<int> all(mesh.triangles.size());
  for(std::size_t i = 0; i < all.size(); i++) all[i] = (int)i;
  std::vector<char> side = bisectPart(mesh, adjacency, all);
  double area[2];
  const double cut = cutOf(mesh, adjacency, side, area);
  // the shortest cut leaving a tenth of the area: one grid line across
  EXPECT_NEAR(cut, 1., 1e-12);
  EXPECT_GE(std::min(area[0], area[1]), 1. - 1e-12);
  EXPECT_EQ(partComponents(adjacency, all, all.size()).size(), 1u);
}

TEST(patchLayout, bisectionCutsWhereTheMapsFail)
{
  // the strip of bisectionCutsAStripStraightAcross, whose shortest cut for
  // its area is in the middle (x = 5, length over area 1 / 5): told the
  // maps fail at the node (3.5, 0.5), the cut goes through it (its
  // triangles on both sides), across the strip (1 / 3.5); told two nodes
  // cross, it puts them on either side; a node at x = 1 (1 / 1: more than
  // twice as long for its area) leaves the cut in the middle
  layoutMesh mesh = meshOf(rectangleGrid(40, 4, 10., 1.));
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<int> all(mesh.triangles.size());
  for(std::size_t i = 0; i < all.size(); i++) all[i] = (int)i;
  auto nodeAt = [&](double x, double y) {
    for(std::size_t n = 0; n < mesh.points.size(); n++)
      if(std::fabs(mesh.points[n].x() - x) < 1e-9 &&
         std::fabs(mesh.points[n].y() - y) < 1e-9)
        return (int)n;
    return -1;
  };
  auto sidesAt = [&](const std::vector<char> &side, int node) {
    int on[2] = {0, 0};
    for(std::size_t t = 0; t < all.size(); t++)
      for(int k = 0; k < 3; k++)
        if(mesh.triangles[t][k] == node) on[(int)side[t]]++;
    return std::array<int, 2>{{on[0], on[1]}};
  };
  partCheck failing{false, "its conformal maps fold", false};
  const int v = nodeAt(3.5, 0.5);
  ASSERT_GE(v, 0);
  failing.cutThrough = {v};
  bool atFailure = false;
  std::vector<char> side =
    bisectPart(mesh, adjacency, all, 0, failing, &atFailure);
  EXPECT_TRUE(atFailure);
  std::array<int, 2> on = sidesAt(side, v);
  EXPECT_GT(on[0], 0);
  EXPECT_GT(on[1], 0);
  double area[2];
  EXPECT_NEAR(cutOf(mesh, adjacency, side, area), 1., 1e-12);
  EXPECT_NEAR(std::min(area[0], area[1]), 3.5, 1e-12);
  // a pair to part: nodes at x = 6 and x = 7
  partCheck crossing{false, "its conformal maps fold", false};
  const int a = nodeAt(6., 0.5), b = nodeAt(7., 0.5);
  crossing.cutApart = {{{a, b}}};
  side = bisectPart(mesh, adjacency, all, 0, crossing);
  const std::array<int, 2> onA = sidesAt(side, a), onB = sidesAt(side, b);
  EXPECT_TRUE((onA[0] == 0 && onB[1] == 0) || (onA[1] == 0 && onB[0] == 0));
  EXPECT_NEAR(cutOf(mesh, adjacency, side, area), 1., 1e-12);
  // too far off the middle, and without any place: the middle
  partCheck far{false, "its conformal maps fold", false};
  far.cutThrough = {nodeAt(1., 0.5)};
  for(const partCheck &c : {far, partCheck()}) {
    side = bisectPart(mesh, adjacency, all, 0, c, &atFailure);
    EXPECT_FALSE(atFailure);
    cutOf(mesh, adjacency, side, area);
    EXPECT_NEAR(std::min(area[0], area[1]), 5., 1e-12);
  }
}

TEST(patchLayout, aPartFailingAtANodeIsCutThroughItOnce)
{
  // a verifier refusing a part that holds every triangle around the node
  // (3.5, 0.5), telling where: one cut, through the node; told nothing, the
  // cuts halve the part around it level after level
  layoutMesh mesh = meshOf(rectangleGrid(40, 4, 10., 1.));
  int v = -1;
  for(std::size_t n = 0; n < mesh.points.size(); n++)
    if(std::fabs(mesh.points[n].x() - 3.5) < 1e-9 &&
       std::fabs(mesh.points[n].y() - 0.5) < 1e-9)
      v = (int)n;
  ASSERT_GE(v, 0);
  std::vector<int> fan;
  for(std::size_t t = 0; t < mesh.triangles.size(); t++)
    for(int k = 0; k < 3; k++)
      if(mesh.triangles[t][k] == v) fan.push_back((int)t);
  for(bool tell : {true, false}) {
    partVerifier verify = [&](const std::vector<int> &part) {
      partCheck c;
      std::size_t held = 0;
      for(int t : part) held += std::count(fan.begin(), fan.end(), t);
      if(held == fan.size()) {
        c = partCheck{false, "its conformal maps fold", false};
        if(tell) c.cutThrough = {v};
      }
      return c;
    };
    layoutResult r = computePatchLayout(mesh, layoutParameters(), verify);
    if(tell) {
      ASSERT_EQ(r.splits.size(), 1u);
      EXPECT_EQ(r.numPatches, 2);
      EXPECT_TRUE(r.splits[0].atFailure);
    }
    else
      EXPECT_GE(r.splits.size(), 3u);
    EXPECT_TRUE(r.unverified.empty()) << tell;
  }
}

TEST(patchLayout, coarseBisectionCutsALongStripAcrossToo)
{
  // 4000 triangles, the Fiedler vector of about 100 clusters: a cut across
  // the strip, nearly as short as the exact one
  layoutMesh mesh = meshOf(rectangleGrid(200, 10, 20., 1.));
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<int> all(mesh.triangles.size());
  for(std::size_t i = 0; i < all.size(); i++) all[i] = (int)i;
  for(std::size_t coarse : {std::size_t(0), std::size_t(100)}) {
    std::vector<char> side = bisectPart(mesh, adjacency, all, coarse);
    double area[2];
    const double cut = cutOf(mesh, adjacency, side, area);
    // exact: one grid line; coarse: a step or two off it (measured 1.04)
    EXPECT_GE(cut, 1. - 1e-12) << coarse;
    EXPECT_LE(cut, coarse ? 1.1 : 1. + 1e-12) << coarse;
    EXPECT_GE(std::min(area[0], area[1]), 2. - 1e-12) << coarse;
    std::vector<int> half;
    for(std::size_t t = 0; t < all.size(); t++)
      if(side[t]) half.push_back((int)t);
    EXPECT_EQ(partComponents(adjacency, half, all.size()).size(), 1u);
  }
}

TEST(patchLayout, partsRefusedForTheirSizeAreCutCoarsely)
{
  // a verifier refusing more than 1000 triangles for their number alone:
  // the 4000-triangle strip cut by coarse Fiedler vectors (100 clusters)
  // into parts of 1000 or fewer (4 to 8: the cuts are near the middles),
  // every cut in two pieces
  layoutMesh mesh = meshOf(rectangleGrid(200, 10, 20., 1.));
  layoutParameters p;
  p.coarseCutNodes = 100;
  int refused = 0;
  partVerifier verify = [&refused](const std::vector<int> &part) {
    partCheck c;
    if(part.size() > 1000) {
      c = partCheck{false, "too large", true};
      refused++;
    }
    return c;
  };
  layoutResult r = computePatchLayout(mesh, p, verify);
  EXPECT_GE(r.numPatches, 4);
  EXPECT_LE(r.numPatches, 8); // measured 7
  EXPECT_EQ(refused, r.numPatches - 1);
  EXPECT_TRUE(r.unverified.empty());
  std::vector<int> count(r.numPatches, 0);
  for(int q : r.patch) count[q]++;
  for(int c : count) EXPECT_LE(c, 1000);
}

TEST(patchLayout, coarseCadFacesAreNotNoise)
{
  // A box of 12 triangles, its 12 edges sharp: 6 faces, none of them noise
  // although each is as small as the mean edge length squared
  layoutMesh mesh;
  for(int i = 0; i < 8; i++)
    mesh.points.push_back(SPoint3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto &q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
    for(int k = 0; k < 4; k++)
      mesh.featureEdges.push_back({q[k], q[(k + 1) % 4]});
  }
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<char> feature(adjacency.edges.size(), 0);
  for(const auto &f : mesh.featureEdges)
    feature[adjacency.find(f[0], f[1])] = 1;
  int n = 0;
  std::vector<int> patch = featurePatches(mesh, adjacency, feature, n);
  EXPECT_EQ(n, 6);
  gmsh::option::setNumber("Mesh.CompoundNoiseSize", 0);
  layoutParameters p = reparamLayoutParameters(mesh);
  EXPECT_EQ(mergeNoisePatches(mesh, adjacency, p, patch, n), 0);
  EXPECT_EQ(n, 6);
  // the same faces among 10000 others are noise: 1 % of the area
  p.noiseArea = 2.;
  EXPECT_EQ(mergeNoisePatches(mesh, adjacency, p, patch, n), 5);
  EXPECT_EQ(n, 1);
}

TEST(patchLayout, classifySurfacesMeshesClosedSurfacesWhole)
{
  for(const testTriangulation &t : {sphere(48, 24), torus(64, 16, 2., 0.6)}) {
    for(const auto &l : remeshWithRecipe(t, 0.1))
      EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    gmsh::vectorpair faces;
    gmsh::model::getEntities(faces, 2);
    EXPECT_GE(faces.size(), 2u);
    EXPECT_TRUE(surfacesWithoutElements().empty());
    // closed: every edge of the new mesh has two triangles (no hole)
    std::size_t nonManifold = 0;
    EXPECT_TRUE(freeMeshEdges(&nonManifold).empty());
    EXPECT_EQ(nonManifold, 0u);
  }
}

TEST(patchLayout, crowdingIsTheSmallestAreaShareRatio)
{
  // Two triangles of equal 3D area; the map gives one 1/4 and the other 3/4
  // of the (u, v) area: ratios 0.5 and 1.5
  std::vector<SPoint3> xyz = {SPoint3(0, 0, 0), SPoint3(1, 0, 0),
                              SPoint3(1, 1, 0), SPoint3(0, 1, 0)};
  std::vector<int> triangles = {0, 1, 2, 0, 2, 3};
  std::vector<SPoint2> uv = {SPoint2(0, 0), SPoint2(1, 0), SPoint2(1, 0.5),
                             SPoint2(0, 1)};
  // uv areas (twice): (0,0),(1,0),(1,0.5): 0.5; (0,0),(1,0.5),(0,1): 1
  EXPECT_NEAR(mapCrowding(uv, xyz, triangles), (0.5 / 1.5) / 0.5, 1e-15);
  // a similarity does not crowd
  std::vector<SPoint2> same = {SPoint2(0, 0), SPoint2(2, 0), SPoint2(2, 2),
                               SPoint2(0, 2)};
  EXPECT_NEAR(mapCrowding(same, xyz, triangles), 1., 1e-15);
  // a collapsed image crowds to 0
  std::vector<SPoint2> flat = {SPoint2(0, 0), SPoint2(1, 0), SPoint2(1, 0),
                               SPoint2(0, 1)};
  EXPECT_NEAR(mapCrowding(flat, xyz, triangles), 0., 1e-15);
}

TEST(patchLayout, partsMeshAboveGmshBoundOnPatchSizeAreCut)
{
  // Mesh.ReparamMaxTriangles bounds Reparam's patches as it does Gmsh's
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  addDiscreteSurface(rectangleGrid(20, 20, 1., 1.));
  gmsh::option::setNumber("Mesh.ReparamMaxTriangles", 300);
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  gmsh::option::setNumber("Mesh.ReparamMaxTriangles", 250000);
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  EXPECT_GE(faces.size(), 800u / 300u + 1);
  for(const auto &f : faces) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes, f.second);
    EXPECT_LE(tags.size(), 300u);
  }
}

TEST(patchLayout, longStripsAreCutOnlyWhereTheyWindAround)
{
  // A flat strip 40 times longer than wide: its conformal map is a
  // similarity, no cut. A ramp of 1.5 turns: both conformal maps fold, and
  // mean value would squeeze it; it is cut until its parts map conformally
  layoutMesh flat = meshOf(rectangleGrid(200, 5, 40., 1.));
  layoutResult r = layoutWithMaps(flat, layoutParameters());
  EXPECT_EQ(r.numPatches, 1);
  EXPECT_TRUE(r.splits.empty());

  layoutMesh ramp = meshOf(helicoidStrip(120, 6, 1.5, 1., 2., 0.05));
  r = layoutWithMaps(ramp, layoutParameters());
  EXPECT_GE(r.numPatches, 2);
  EXPECT_LE(r.numPatches, 6);
  ASSERT_FALSE(r.splits.empty());
  EXPECT_NE(r.splits[0].reason.find("conformal maps fold"), std::string::npos)
    << r.splits[0].reason;
  expectDiskPatches(ramp, r);
}

TEST(patchLayout, aRefusedRampSaysWhereItsMapsFold)
{
  // the ramp of 1.5 turns refused because its conformal maps fold: the
  // verification names pairs of its boundary nodes whose edges cross (at
  // most maxFoldPairs for each of the two conformal maps), on the ramp
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  gmshTriangulation g(helicoidStrip(120, 6, 1.5, 1., 2., 0.05));
  mapFailurePlace where;
  partCheck c = reparamVerifyPart(g.triangles, &where);
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.reason.find("conformal maps fold"), std::string::npos);
  EXPECT_GE(where.apart.size(), 1u);
  EXPECT_LE(where.apart.size(), 2 * maxFoldPairs);
  for(const auto &pr : where.apart)
    for(MVertex *v : pr)
      EXPECT_NE(std::find(g.vertices.begin(), g.vertices.end(), v),
                g.vertices.end());
  // a part its first map flattens says nothing
  gmshTriangulation flat(rectangleGrid(10, 2, 5., 1.));
  mapFailurePlace none;
  EXPECT_TRUE(reparamVerifyPart(flat.triangles, &none).ok);
  EXPECT_TRUE(none.through.empty() && none.apart.empty());
}

TEST(patchLayout, largenessComparesTheAreaWithTheDiskOfTheBoundary)
{
  // a flat disk: 1 (to the polygon's discretization); a hemisphere: 2; a
  // tube closed at one end (a sock) much more: it is cut
  auto largeness = [](const testTriangulation &t) {
    std::vector<int> nodes;
    for(const auto &tri : t.triangles)
      nodes.insert(nodes.end(), tri.begin(), tri.end());
    return boundaryLargeness(t.points, nodes);
  };
  EXPECT_NEAR(largeness(polarDisk(20, 200)), 1., 1e-3);
  EXPECT_NEAR(largeness(hemisphere(40, 200)), 2., 2e-2);
  testTriangulation sock = sphericalCap(40, 64, 0.9 * M_PI);
  EXPECT_GT(largeness(sock), reparamMaxLargeness);
  EXPECT_LT(largeness(sphericalCap(40, 64, 0.5 * M_PI)), reparamMaxLargeness);
}

TEST(patchLayout, holesTouchingAtANodeStillTouchInTheMesh)
{
  // two square holes of a 6 x 6 grid touching at the node (1/3, 1/3): the
  // curves around them end there (patches/0012), so the new mesh has a node
  // there too, with the four boundary edges of both holes
  testTriangulation t = gridWithout(6, {{1, 1}, {2, 2}});
  testTriangulation used; // without the nodes of no triangle
  std::map<int, int> index;
  for(auto &tri : t.triangles)
    for(int &n : tri) {
      auto it = index.insert({n, (int)used.points.size()});
      if(it.second) used.points.push_back(t.points[n]);
      n = it.first->second;
    }
  used.triangles = t.triangles;
  for(const auto &l : remeshWithRecipe(used, 0.08))
    EXPECT_EQ(l.find("Error"), std::string::npos) << l;
  EXPECT_TRUE(surfacesWithoutElements().empty());
  std::map<std::size_t, int> freeEdgesAt;
  for(const auto &e : freeMeshEdges()) {
    freeEdgesAt[e.first]++;
    freeEdgesAt[e.second]++;
  }
  int atPinch = 0;
  for(const auto &n : freeEdgesAt) {
    std::vector<double> p, par;
    gmsh::model::mesh::getNode(n.first, p, par);
    if(std::hypot(p[0] - 1. / 3., p[1] - 1. / 3.) < 1e-12) atPinch = n.second;
  }
  EXPECT_EQ(atPinch, 4);
}

namespace {

  partCheck verified(const testTriangulation &t)
  {
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    gmshTriangulation g(t);
    return reparamVerifyPart(g.triangles);
  }

} // namespace

TEST(patchLayout, partsFailingWhateverTheirMapFailBeforeIt)
{
  // a sock, much larger than the disk its boundary bounds: refused with
  // that reason, whatever its map
  partCheck c = verified(sphericalCap(20, 32, 0.9 * M_PI));
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.reason.find("times larger than the disk its boundary bounds"),
            std::string::npos);
  // a disk with a hole filled on its mean plane passes, and its map
  const testTriangulation holed = polarDiskWithHoles(8, 32, {{{3, 5, 4, 10}}});
  {
    gmshTriangulation g(holed);
    EXPECT_TRUE(reparamHolesFillable(g.triangles));
  }
  EXPECT_TRUE(verified(holed).ok);
  // as without holes
  gmshTriangulation disk(polarDisk(6, 24));
  EXPECT_TRUE(reparamHolesFillable(disk.triangles));
}

TEST(patchLayout, aPatchBuiltForTheChecksServesTheMap)
{
  // the layout builds a part's patch once, for its holes' check and for its
  // map: the map of the patch given is the map of the triangles, to the bit,
  // and the patch is taken
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  gmshTriangulation g(polarDiskWithHoles(8, 32, {{{3, 5, 4, 10}}}));
  std::vector<SPoint2> uv[2];
  std::vector<SPoint3> xyz[2];
  std::vector<int> tri[2];
  std::string why[2];
  ASSERT_EQ(
    reparamTryParametrization(g.triangles, uv[0], xyz[0], tri[0], why[0]), 1);
  trianglePatch patch = patchOfTriangles(g.triangles);
  EXPECT_TRUE(reparamHolesFillable(patch));
  EXPECT_EQ(patch.patch.boundaryLoops.size(), 2u);
  ASSERT_EQ(reparamTryParametrization(g.triangles, uv[1], xyz[1], tri[1],
                                      why[1], nullptr, &patch),
            1);
  EXPECT_TRUE(patch.nodes.empty());
  EXPECT_EQ(tri[1], tri[0]);
  ASSERT_EQ(uv[1].size(), uv[0].size());
  for(std::size_t i = 0; i < uv[0].size(); i++) {
    EXPECT_EQ(uv[1][i].x(), uv[0][i].x());
    EXPECT_EQ(uv[1][i].y(), uv[0][i].y());
    EXPECT_EQ(xyz[1][i].distance(xyz[0][i]), 0.);
  }
}
