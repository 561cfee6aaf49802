# Reparam tutorial 1, with Gmsh's Python API: remeshing a poor STL
# triangulation with Gmsh's own parametrization and with Reparam's.
#
#   PYTHONPATH=build/gmsh python3 tutorials/t1_remesh_stl.py
#
# (build/gmsh holds the built libgmsh and its gmsh.py)

import math
import os
import sys

import gmsh

here = os.path.dirname(os.path.abspath(__file__))
gmsh.initialize(sys.argv)
gmsh.option.setNumber("General.Terminal", 0)

names = {0: "Gmsh built-in", 3: "Reparam mean value"}
for parametrization in (0, 3):
    gmsh.clear()
    # (set after createGeometry, it acts too: the surfaces are parametrized
    # again at the next generate)
    gmsh.option.setNumber("Mesh.CompoundParametrization", parametrization)
    gmsh.merge(os.path.join(here, "dome.stl"))
    gmsh.model.mesh.classifySurfaces(40 * math.pi / 180, True, True, math.pi)
    gmsh.model.mesh.createGeometry()
    gmsh.option.setNumber("Mesh.MeshSizeMin", 0.05)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.05)
    gmsh.model.mesh.generate(2)
    triangles, _ = gmsh.model.mesh.getElementsByType(2)
    print("%-20s %d triangles" % (names[parametrization], len(triangles)))

# Reparam's plugins from the API: how conformal the last parametrization is
# (Plugin(Parametrization)), and kappa per triangle (Plugin(SurfaceMeshQuality))
gmsh.plugin.setNumber("Parametrization", "SurfaceTag", -1)
gmsh.plugin.run("Parametrization")
gmsh.plugin.setNumber("SurfaceMeshQuality", "CreateViews", 1)
gmsh.plugin.run("SurfaceMeshQuality")
for tag in gmsh.view.getTags():
    name = gmsh.option.getString("View[%d].Name" % gmsh.view.getIndex(tag))
    if name not in ("angle distortion", "kappa"):
        continue
    # list-based triangles: 9 coordinates, then one value per corner
    types, counts, data = gmsh.view.getListData(tag)
    values = [d[9::12] for t, d in zip(types, data) if t == "ST"][0]
    print("%-20s mean %.3f over %d triangles" %
          (name, sum(values) / len(values), len(values)))

gmsh.finalize()
