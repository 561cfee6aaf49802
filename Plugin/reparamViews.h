// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The views Reparam's plugins create. List-based (PViewDataList), like those
// of Gmsh's own plugins: they save as .pos in batch and draw in the GUI.

#ifndef REPARAM_VIEWS_H
#define REPARAM_VIEWS_H

#include <string>
#include <vector>
#include "surfaceMesh.h"

class PView;

namespace reparam {

// One value per element of `mesh` (triangles first, then quadrangles),
// drawn constant over the element
PView *elementValueView(const std::string &name, const surfaceMesh &mesh,
                        const std::vector<double> &values);

// One value per node of `mesh`, interpolated over its elements
PView *nodalValueView(const std::string &name, const surfaceMesh &mesh,
                      const std::vector<double> &values);

// Percentage of `values` in each of `bins` equal bins of [low, high]
// (values outside go to the first or last bin)
std::vector<double> histogram(const std::vector<double> &values, int bins,
                              double low, double high);

// A 2D plot of `shares` (from histogram, in %) against the bin centres,
// x axis labelled `name`, the view named `name`_histogram
PView *histogramView(const std::string &name, const std::vector<double> &shares,
                     double low, double high);

} // namespace reparam

#endif
