// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Plugin(SurfaceMeshQuality): quality of the triangles of any surface mesh
// (stock Gmsh meshes too), for comparing parametrizations and meshers.

#ifndef SURFACE_MESH_QUALITY_H
#define SURFACE_MESH_QUALITY_H

#include "Plugin.h"

class GMSH_SurfaceMeshQualityPlugin : public GMSH_PostPlugin {
public:
  std::string getName() const { return "SurfaceMeshQuality"; }
  std::string getShortHelp() const
  {
    return "Aspect ratio (kappa) of surface triangles";
  }
  std::string getHelp() const;
  std::string getAuthor() const { return "Reparam"; }
  int getNbOptions() const;
  StringXNumber *getOption(int iopt);
  PView *execute(PView *);
};

#endif
