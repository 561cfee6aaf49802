// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The sharp creases left inside a discrete face (Mesh/creaseChains.h) kept
// as curves embedded in it when CreateGeometry has parametrized it, so that
// Gmsh's planar meshers put edges along them instead of cutting across.

#ifndef REPARAM_CREASE_CURVES_H
#define REPARAM_CREASE_CURVES_H

#include <vector>
#include "SPoint3.h"

class GFace;
class MVertex;

// gf's input nodes, their points and its triangles (3 node indices each):
// the chains of sharp edges the last patch layout left inside gf, longer
// than twice the layout's noise size, kept half that size away from gf's
// curves, become discrete curves embedded in gf; returns how many
int reparamEmbedCreaseCurves(GFace *gf, const std::vector<MVertex *> &nodes,
                             const std::vector<SPoint3> &points,
                             const std::vector<int> &triangleNodes);

// While gf is recombined into quadrangles (Mesh.RecombineAll or the face's
// Recombine): its crease curves taken out of it and their 1D meshes
// deleted (Blossom pairs no triangles across an embedded curve, so the
// pieces the creases close off must each have an even count of triangles:
// "Perfect Match failed" on fertility); the end puts the curves back
void reparamHideCreaseCurvesFromQuads(GFace *gf);
void reparamRestoreCreaseCurves(GFace *gf);

#endif
