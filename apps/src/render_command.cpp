// `hullcover render SCENE [HULLS] -o OUT.png`: a picture of a scene and a
// set of hulls (hullcover's or any other tool's), each hull in its own
// colour, as in the paper's figures.

#include "commands.h"
#include "scene_loading.h"

#include "render/scene_picture.h"

#include "hullcover/validate/hull_set.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace hullcover::app {
namespace {

struct RenderCommandOptions {
  std::string scene, hulls, out;
  std::string view = "iso", size = "1200x900", up = "y";
  bool cut = false;
  ImportLimits limits;
};

int bad_input(const Status& status) {
  std::fprintf(stderr, "hullcover: error: %s\n", status.message().c_str());
  return kExitBadInput;
}

// The command line's words as picture options, or the first one that is wrong.
Result<render::PictureOptions> picture_options(const RenderCommandOptions& o) {
  render::PictureOptions options;
  const Result<render::ViewAngles> view = render::parse_view(o.view);
  if (!view.ok()) return view.status();
  const Result<render::ImageSize> size = render::parse_image_size(o.size);
  if (!size.ok()) return size.status();
  const Result<render::UpAxis> up = render::parse_up_axis(o.up);
  if (!up.ok()) return up.status();
  options.view = view.value();
  options.size = size.value();
  options.up = up.value();
  options.cut = o.cut;
  return options;
}

int run_render_command(const RenderCommandOptions& o) {
  // The options first: a wrong size is reported before a large scene loads.
  const Result<render::PictureOptions> options = picture_options(o);
  if (!options.ok()) return bad_input(options.status());
  const std::optional<LoadedScene> scene = load_scene(o.scene, std::nullopt, o.limits);
  if (!scene) return kExitBadInput;
  std::optional<validate::HullSet> hulls;
  if (!o.hulls.empty()) {
    Result<validate::HullSet> loaded = validate::load_hull_set(o.hulls);
    if (!loaded.ok()) return bad_input(loaded.status());
    hulls = std::move(loaded).value();
  }
  render::PictureContent content;
  content.scene = &scene->prepared.mesh;
  content.hulls = hulls ? &hulls->hulls : nullptr;
  if (Status written = render::write_scene_picture_png(content, options.value(), o.out); !written.ok())
    return bad_input(written);
  std::printf("wrote %s: %dx%d, %zu faces, %zu hulls%s\n", o.out.c_str(), options.value().size.width,
              options.value().size.height, scene->prepared.mesh.triangles.size(), hulls ? hulls->hulls.size() : 0,
              o.cut ? ", cut away" : "");
  return kExitSuccess;
}

// The cut-away's rule (render/cut_away.h), its numbers from the constants
// that apply it.
std::string cut_rule_help() {
  char text[1024];
  std::snprintf(text, sizeof text,
                "Cut away roofs and front walls to show the inside (the paper's Fig. 1). Hulls are judged whole,\n"
                "scene triangles alone, by the outward normal n of their largest facet. Left out: roofs, every\n"
                "vertex above %g%% of the scene box's height; and front walls, n within %g deg of horizontal, its\n"
                "horizontal part (either sign) within %g deg of the camera's horizontal direction, every vertex in\n"
                "the %g%% of the box nearest the camera along that horizontal normal. Seen from straight above or\n"
                "below: roofs only",
                100.0 * render::kRoofCutHeightFraction, render::kWallTiltDeg, render::kWallFacingDeg,
                100.0 * render::kFrontCutFraction);
  return text;
}

} // namespace

void register_render_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Draw a scene and its hulls to a PNG, as in the paper's figures: the scene's faces grey (lit from\n"
      "whichever side faces the camera), each hull flat shaded in a saturated colour of its own (never red),\n"
      "painted far to near (polygons cut along small screen cells, ordered where they overlap and split\n"
      "where they cross; a hull facet is drawn over a scene face in its plane). The perspective camera\n"
      "frames the scene's bounding box. Exit status 0 written, 2 unreadable input or bad usage.");
  cmd->add_option("SCENE", o->scene, "The scene (any format hullcover reads)")->required();
  cmd->add_option("HULLS", o->hulls,
                  "Hulls to draw over it: a runtime file (.hcw) or an OBJ with one o/g group per hull (hullcover's,\n"
                  "V-HACD's, ...); none: the scene alone");
  cmd->add_option("-o,--out", o->out, "The PNG file to write (atomically)")->required();
  cmd->add_option("--view", o->view,
                  "Where the camera stands: iso (azimuth 45, elevation 35.26), top (0, 90), front (0, 0), or\n"
                  "AZIMUTH,ELEVATION in degrees (azimuth from the front towards the right, elevation in [-90, 90])")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT in pixels, each from 16 to 8192")->capture_default_str();
  cmd->add_option("--up", o->up, "The scene's up axis: y (OBJ, glTF; front is +z), z (front is -y) or x (front is -z)")
      ->capture_default_str();
  cmd->add_flag("--cut", o->cut, cut_rule_help());
  add_import_limit_options(*cmd, o->limits);
  cmd->callback([o, &exit_status] { exit_status = run_render_command(*o); });
}

} // namespace hullcover::app
