// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Orientation of the new mesh of a discrete face (called from
// orientMeshGFace, patches/0004, which declares it too).

#ifndef REPARAM_ORIENT_H
#define REPARAM_ORIENT_H

class GFace;

#endif
