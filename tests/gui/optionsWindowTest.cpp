// Reparam - the Compound tab of Gmsh's options window (Tools > Options >
// Mesh, patches/0017), driven as a user would: the map chosen in its
// widget, not by the option string, reaches the mesher (the report names
// it), also when chosen after tutorial 1 is loaded and meshed, and a reload
// keeps it, and for tutorial 2's compound; every label fits its widget; the
// window and the open list of maps look like the stored reference images
// (within a tolerance: fonts render alike on the same Debian, not byte for
// byte).
//
//   reparamGuiTest TUTORIALS_DIR REFERENCE.png LIST_REFERENCE.png
//                  [SCREENSHOT.ppm LIST_SCREENSHOT.ppm]
//
// Run under a display (CTest: xvfb-run). Exit code 0: passed; 1: failed
// (what and why printed).

#include <FL/Fl.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Menu_Window.H>
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

  // Whether every label of the Compound tab's choices and buttons is drawn
  // whole (Fl_Choice: its text left of the arrow box, FLTK 1.3's draw)
  bool labelsFit(optionWindow *o, std::string &cut)
  {
    for(int i : {40, 41}) {
      Fl_Choice *c = o->mesh.choice[i];
      fl_font(c->textfont(), c->textsize());
      const int dx = Fl::box_dx(c->box()),
                h = c->h() - 2 * Fl::box_dy(c->box());
      const int room = c->w() - 2 * dx - std::min(h, 20) - 4;
      for(int k = 0; k < c->size() - 1; k++) {
        const char *label = c->menu()[k].label();
        if(label && fl_width(label) > room) cut = label;
      }
    }
    for(int i = 40; i < 44; i++) {
      Fl_Check_Button *b = o->mesh.butt[i];
      fl_font(b->labelfont(), b->labelsize());
      // the box, then the label, inside the button
      if(fl_width(b->label()) + b->h() > b->w()) cut = b->label();
    }
    return cut.empty();
  }

  // The list of maps as the choice opens it: a timer takes its picture
  // and closes it (Escape), as the menu runs its own event loop
  image openListShot;
  void shootOpenList(void *)
  {
    Fl_Window *menu = Fl::first_window();
    if(menu && menu->as_window() && dynamic_cast<Fl_Menu_Window *>(menu))
      openListShot = screenshot(menu);
    Fl::e_keysym = FL_Escape;
    Fl::handle(FL_KEYBOARD, Fl::first_window());
  }

  bool looksLike(const image &shot, const std::string &reference,
                 const std::string &what, std::string &why)
  {
    image expected;
    if(!readPng(reference, expected)) {
      why = "no reference image " + reference;
      return false;
    }
    double mean = 0., share = 0.;
    if(!compare(shot, expected, mean, share)) {
      why = what + " is " + std::to_string(shot.width) + " x " +
            std::to_string(shot.height) + ", the reference " +
            std::to_string(expected.width) + " x " +
            std::to_string(expected.height);
      return false;
    }
    std::cout << what << ": mean difference " << mean << " / 255, "
              << 100. * share << " % of the pixels far from the reference"
              << std::endl;
    // 0 and 0 % on Debian bookworm's Xvfb; another label of the choice
    // differs in 0.26 % of the window's pixels
    if(mean > 1. || share > 0.001) {
      why = what + " differs from the reference image";
      return false;
    }
    return true;
  }

  // Mesh 2 of the current model: the log, and whether a line names the map
  // `name` in the report and whether one says surfaces were parametrized
  // again; an Error line fails
  struct meshed {
    bool named = false, again = false;
    std::string error;
  };
  meshed mesh2(const std::string &name)
  {
    gmsh::logger::start();
    gmsh::model::mesh::generate(2);
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    meshed m;
    for(const std::string &l : log) {
      m.named = m.named || std::regex_search(
                             l, std::regex("Reparam: [0-9]+ +" + name + " "));
      m.again = m.again || l.find("parametrized again") != std::string::npos;
      if(l.find("Error") != std::string::npos) m.error = l;
    }
    return m;
  }

} // namespace

int main(int argc, char **argv)
{
  if(argc < 4)
    return fail("usage: reparamGuiTest TUTORIALS_DIR REFERENCE.png "
                "LIST_REFERENCE.png [SCREENSHOT.ppm LIST_SCREENSHOT.ppm]");
  const std::string tutorials = argv[1], reference = argv[2],
                    listReference = argv[3];
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
  std::string cut;
  if(!labelsFit(o, cut)) return fail("the label \"" + cut + "\" is cut");
  // the spectral conformal map, chosen in the widget
  o->mesh.choice[40]->value(5);
  o->mesh.choice[40]->do_callback();
  if(option("Mesh.CompoundParametrization") != 5)
    return fail("the widget did not set Mesh.CompoundParametrization");

  std::string why;
  const image shot = screenshot(o->win);
  if(argc > 4) writePpm(argv[4], shot);
  if(!looksLike(shot, reference, "the window", why)) return fail(why);
  // the list of maps, open
  Fl_Choice *maps = o->mesh.choice[40];
  Fl::add_timeout(0.5, shootOpenList);
  const Fl_Menu_Item *picked =
    maps->menu()->pulldown(maps->x() + o->win->x(), maps->y() + o->win->y(),
                           maps->w(), maps->h(), maps->mvalue());
  if(picked) return fail("the open list picked a map by itself");
  if(openListShot.rgb.empty()) return fail("no picture of the open list");
  if(argc > 5) writePpm(argv[5], openListShot);
  if(!looksLike(openListShot, listReference, "the open list", why))
    return fail(why);

  // tutorial 1 as a user opens it: the map of the window (spectral)
  gmsh::open(tutorials + "/t1_remesh_stl.geo");
  meshed m = mesh2("spectral");
  if(!m.error.empty()) return fail("log: " + m.error);
  if(!m.named) return fail("the report does not name the spectral map");
  // another map chosen in the window once the file is loaded and meshed:
  // the next Mesh > 2D parametrizes again and meshes with it
  maps->value(4);
  maps->do_callback();
  m = mesh2("LSCM");
  if(!m.error.empty()) return fail("log: " + m.error);
  if(!m.again || !m.named)
    return fail("the map chosen after loading is not the one meshed");
  // File > Reload keeps the window's choice (the tutorial leaves the map to
  // the option)
  gmsh::open(tutorials + "/t1_remesh_stl.geo");
  if(option("Mesh.CompoundParametrization") != 4 || maps->value() != 4)
    return fail("reloading the tutorial changed the map of the window");
  m = mesh2("LSCM");
  if(!m.named || m.again)
    return fail("the reloaded tutorial is not meshed with the window's map");
  // tutorial 2's Compound Surface, parametrized when meshed: the map
  // chosen in the window after loading
  gmsh::open(tutorials + "/t2_compound.geo");
  maps->value(3);
  maps->do_callback();
  m = mesh2("MV");
  if(!m.error.empty()) return fail("log: " + m.error);
  if(!m.named) return fail("tutorial 2 is not meshed with the window's map");
  std::cout << "maps from the options window: spectral, then finite element "
               "conformal chosen after loading tutorial 1, in the report; "
               "kept on reload; mean value for tutorial 2's compound"
            << std::endl;
  gmsh::finalize();
  return 0;
}
