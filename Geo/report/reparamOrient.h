// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Orientation of the new mesh of a discrete face (called from
// orientMeshGFace, patches/0004, which declares it too).

#ifndef REPARAM_ORIENT_H
#define REPARAM_ORIENT_H

class GFace;

// Reverses every element of the mesh of discrete face gf if most of them
// point against the input under them (meshFidelity::inverted); warns about
// the elements left pointing against it. False (and nothing done) for other
// faces and for Gmsh's own map (Mesh.CompoundParametrization = 0)
bool reparamOrientMeshedFace(GFace *gf);

#endif
