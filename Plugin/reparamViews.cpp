// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "PView.h"
#include "PViewDataList.h"
#include "PViewOptions.h"
#include "reparamViews.h"

namespace reparam {

namespace {

  // Coordinates of one element in the list format: all x, then all y, z
  template <std::size_t N>
  void pushCoordinates(std::vector<double> &list, const surfaceMesh &mesh,
                       const std::array<int, N> &element)
  {
    for(int c = 0; c < 3; c++)
      for(int node : element) list.push_back(mesh.points[node][c]);
  }

  PView *newView(const std::string &name, PViewDataList *&data)
  {
    PView *view = new PView();
    data = dynamic_cast<PViewDataList *>(view->getData());
    data->setName(name);
    data->setFileName(name + ".pos");
    return view;
  }

} // namespace

PView *elementValueView(const std::string &name, const surfaceMesh &mesh,
                        const std::vector<double> &values)
{
  PViewDataList *data;
  PView *view = newView(name, data);
  const std::size_t numTriangles = mesh.triangles.size();
  for(std::size_t i = 0; i < numTriangles; i++) {
    pushCoordinates(data->ST, mesh, mesh.triangles[i]);
    data->ST.insert(data->ST.end(), 3, values[i]);
    data->NbST++;
  }
  for(std::size_t i = 0; i < mesh.quadrangles.size(); i++) {
    pushCoordinates(data->SQ, mesh, mesh.quadrangles[i]);
    data->SQ.insert(data->SQ.end(), 4, values[numTriangles + i]);
    data->NbSQ++;
  }
  data->finalize();
  return view;
}

PView *nodalValueView(const std::string &name, const surfaceMesh &mesh,
                      const std::vector<double> &values)
{
  PViewDataList *data;
  PView *view = newView(name, data);
  for(const auto &t : mesh.triangles) {
    pushCoordinates(data->ST, mesh, t);
    for(int node : t) data->ST.push_back(values[node]);
    data->NbST++;
  }
  for(const auto &q : mesh.quadrangles) {
    pushCoordinates(data->SQ, mesh, q);
    for(int node : q) data->SQ.push_back(values[node]);
    data->NbSQ++;
  }
  data->finalize();
  return view;
}

std::vector<double> histogram(const std::vector<double> &values, int bins,
                              double low, double high)
{
  std::vector<double> shares(std::max(bins, 1), 0.);
  if(values.empty()) return shares;
  const double width = (high - low) / shares.size();
  for(double x : values) {
    int bin = width > 0. ? (int)std::floor((x - low) / width) : 0;
    bin = std::min(std::max(bin, 0), (int)shares.size() - 1);
    shares[bin] += 1.;
  }
  for(double &s : shares) s *= 100. / values.size();
  return shares;
}

PView *histogramView(const std::string &name, const std::vector<double> &shares,
                     double low, double high)
{
  // Gmsh's own 2D plot (x and y lists, axes, x label)
  std::vector<double> x(shares.size()), y(shares);
  const double width = (high - low) / shares.size();
  for(std::size_t i = 0; i < shares.size(); i++) x[i] = low + (i + 0.5) * width;
  return new PView(name, name + "_histogram", x, y);
}
} // namespace reparam

