// Reparam - the Compound tab of Gmsh's options window (Tools > Options >
// Mesh, patches/0017), driven as a user would: the map chosen in its
// widget, not by the option string, reaches the mesher (the report names
// it), and the window looks like the stored reference image (within a
// tolerance: fonts render alike on the same Debian, not byte for byte).
//
//   reparamGuiTest TUTORIALS_DIR REFERENCE.png [SCREENSHOT.ppm]
//
// Run under a display (CTest: xvfb-run). Exit code 0: passed; 1: failed
// (what and why printed).

#include <FL/Fl.H>
#include <FL/Fl_PNG_Image.H>
#include <FL/Fl_Tabs.H>
#include <FL/fl_draw.H>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>
#include <vector>
#include "FlGui.h"
#include "gmsh.h"
#include "optionWindow.h"

using namespace reparam;

namespace {

  struct image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
  };

  bool readPng(const std::string &path, image &im)
  {
    Fl_PNG_Image png(path.c_str());
    if(png.fail() || png.d() < 3 || !png.count()) return false;
    im.width = png.w();
    im.height = png.h();
    const unsigned char *data = (const unsigned char *)png.data()[0];
    const int stride = png.ld() ? png.ld() : png.w() * png.d();
    im.rgb.clear();
    for(int y = 0; y < im.height; y++)
      for(int x = 0; x < im.width; x++)
        for(int c = 0; c < 3; c++)
          im.rgb.push_back(data[y * stride + x * png.d() + c]);
    return true;
  }

  void writePpm(const std::string &path, const image &im)
  {
    std::ofstream f(path, std::ios::binary);
    f << "P6\n" << im.width << " " << im.height << "\n255\n";
    f.write((const char *)im.rgb.data(), im.rgb.size());
  }

  // The options window as drawn on the display
  image screenshot(Fl_Window *win)
  {
    for(int i = 0; i < 20; i++) Fl::wait(0.05);
    Fl::flush();
    win->make_current();
    image im;
    im.width = win->w();
    im.height = win->h();
    unsigned char *pixels = fl_read_image(nullptr, 0, 0, im.width, im.height);
    im.rgb.assign(pixels, pixels + 3 * im.width * im.height);
    delete[] pixels;
    return im;
  }

  // Mean absolute difference per channel (0-255) and share of the pixels
  // that differ by more than 64 in a channel; false if the sizes differ
  bool compare(const image &a, const image &b, double &mean, double &share)
  {
    if(a.width != b.width || a.height != b.height) return false;
    double sum = 0.;
    std::size_t far = 0;
    for(std::size_t p = 0; p < a.rgb.size(); p += 3) {
      int worst = 0;
      for(int c = 0; c < 3; c++) {
        const int d = std::abs((int)a.rgb[p + c] - (int)b.rgb[p + c]);
        sum += d;
        worst = std::max(worst, d);
      }
      far += worst > 64;
    }
    mean = sum / a.rgb.size();
    share = (double)far / (a.rgb.size() / 3);
    return true;
  }

  double option(const std::string &name)
  {
    double value = 0.;
    gmsh::option::getNumber(name, value);
    return value;
  }

  int fail(const std::string &why)
  {
    std::cerr << "FAILED: " << why << std::endl;
    return 1;
  }

} // namespace

int main(int argc, char **argv)
{
  if(argc < 3) return fail("usage: reparamGuiTest TUTORIALS_DIR REFERENCE.png");
  const std::string tutorials = argv[1], reference = argv[2];
  gmsh::initialize();
  gmsh::fltk::initialize();
  optionWindow *o = FlGui::instance()->options;
  // Tools > Options > Mesh, its Compound tab
  o->showGroup(3);
  Fl_Group *tab = o->mesh.choice[40]->parent();
  ((Fl_Tabs *)tab->parent())->value(tab);
  if(option("Mesh.CompoundParametrization") != 6 ||
     o->mesh.choice[40]->value() != 6)
    return fail("the widget does not show the default map (automatic)");
  // the spectral conformal map, chosen in the widget
  o->mesh.choice[40]->value(5);
  o->mesh.choice[40]->do_callback();
  if(option("Mesh.CompoundParametrization") != 5)
    return fail("the widget did not set Mesh.CompoundParametrization");

  const image shot = screenshot(o->win);
  if(argc > 3) writePpm(argv[3], shot);
  image expected;
  if(!readPng(reference, expected))
    return fail("no reference image " + reference);
  double mean = 0., share = 0.;
  if(!compare(shot, expected, mean, share))
    return fail("the window is " + std::to_string(shot.width) + " x " +
                std::to_string(shot.height) + ", the reference " +
                std::to_string(expected.width) + " x " +
                std::to_string(expected.height));
  std::cout << "screenshot: mean difference " << mean << " / 255, "
            << 100. * share << " % of the pixels far from the reference"
            << std::endl;
  // 0 and 0 % on Debian bookworm's Xvfb; the label of another map in the
  // choice (finite element conformal) differs in 0.26 % of the pixels
  if(mean > 1. || share > 0.001)
    return fail("the window differs from the reference image");

  // the recipe on the tutorial's STL: the report names the map
  gmsh::logger::start();
  gmsh::merge(tutorials + "/dome.stl");
  gmsh::model::mesh::classifySurfaces(40. * M_PI / 180., true, true, M_PI);
  gmsh::model::mesh::createGeometry();
  gmsh::model::mesh::generate(2);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  bool spectral = false;
  for(const std::string &l : log) {
    spectral = spectral ||
               std::regex_search(l, std::regex("Reparam: [0-9]+ +spectral "));
    if(l.find("Error") != std::string::npos) return fail("log: " + l);
  }
  if(!spectral) return fail("the report does not name the spectral map");
  std::cout << "map from the options window: spectral conformal, in the report"
            << std::endl;
  gmsh::finalize();
  return 0;
}
