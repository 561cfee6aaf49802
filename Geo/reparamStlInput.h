// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The facets of an STL file as Gmsh reads them (hook in GModel::readSTL,
// patches/0009): a facet with a NaN or infinite coordinate made Gmsh's
// reader crash (its node search box became NaN). Such facets are dropped,
// with one warning; the others are read.

#ifndef REPARAM_STL_INPUT_H
#define REPARAM_STL_INPUT_H

#include <vector>
#include "SBoundingBox3d.h"
#include "SPoint3.h"

// points: per solid, 3 corners per facet. Drops the facets with a
// non-finite corner and recomputes bbox when any was dropped; returns how
// many were
std::size_t reparamDropInvalidStlFacets(std::vector<std::vector<SPoint3> > &points,
                                        SBoundingBox3d &bbox);

#endif
