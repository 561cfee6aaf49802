// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The facets of an STL file as Gmsh reads them (hook in GModel::readSTL,
// patches/0009): a facet with a NaN or infinite coordinate made Gmsh's
// reader crash (its node search box became NaN), and a file cut short was
// refused whole. Such facets are dropped, with one warning; the others are
// read.

#ifndef REPARAM_STL_INPUT_H
#define REPARAM_STL_INPUT_H

#include <vector>
#include "SBoundingBox3d.h"
#include "SPoint3.h"

// points: per solid, 3 corners per facet. Drops the facets with a
// non-finite corner and recomputes bbox when any was dropped; returns how
// many were. An incomplete last facet (a file cut short) is dropped too,
// with a warning; a file left without any facet, or with zero-area ones
// only, is an error.
std::size_t
reparamDropInvalidStlFacets(std::vector<std::vector<SPoint3> > &points,
                            SBoundingBox3d &bbox);

#endif
