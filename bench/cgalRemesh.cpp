// Reparam bench peer: CGAL's isotropic remeshing (Debian's libcgal-dev),
// for bench/speed.sh only (not a dependency of Gmsh, Reparam or the tests).
//
//   cgalRemesh FILE.stl TARGET_EDGE_LENGTH [ITERATIONS=3] [OUT.stl]
//
// Reads the STL as a polygon soup, orients it, remeshes it with the target
// edge length, the borders protected, and prints one line:
//   cgal triangles N seconds S
// (S: the remeshing alone; the process's CPU is measured by the caller).
// With OUT.stl, writes the remeshed surface there (after the timing), for
// the bench's side-by-side quality and distances.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char **argv)
{
  if(argc < 3) {
    std::fprintf(stderr, "usage: %s FILE.stl TARGET [ITERATIONS] [OUT.stl]\n",
                 argv[0]);
    return 2;
  }
  const double target = std::atof(argv[2]);
  const int iterations = argc > 3 ? std::atoi(argv[3]) : 3;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(argv[1], points, polygons)) {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 1;
  }
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const auto start = std::chrono::steady_clock::now();
  PMP::isotropic_remeshing(
    faces(mesh), target, mesh,
    CGAL::parameters::number_of_iterations(iterations)
      .protect_constraints(true));
  const double seconds = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
  std::printf("cgal triangles %lu seconds %g\n",
              (unsigned long)mesh.number_of_faces(), seconds);
  if(argc > 4 && !CGAL::IO::write_polygon_mesh(argv[4], mesh)) {
    std::fprintf(stderr, "cannot write %s\n", argv[4]);
    return 1;
  }
  return 0;
}
