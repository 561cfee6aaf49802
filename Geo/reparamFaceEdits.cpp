// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "GFace.h"
#include "reparamFaceEdits.h"

std::string reparamTagList(const std::vector<GFace *> &faces)
{
  std::string list;
  for(GFace *gf : faces)
    list += (list.empty() ? "" : ", ") + std::to_string(gf->tag());
  return list;
}
