#include "scenes/scenario/render_choices.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace landsim::scenes {

void override_view_sizes(Scenario& s, std::optional<int> width, std::optional<int> height) {
  for (ViewSettings& v : s.views) {
    const double aspect = static_cast<double>(v.width) / v.height;
    const int old_height = v.height;
    if (width) v.width = *width;
    if (height) v.height = *height;
    if (width && !height) v.height = std::max(1, static_cast<int>(std::lround(v.width / aspect)));
    if (height && !width) v.width = std::max(1, static_cast<int>(std::lround(v.height * aspect)));
    check_image_size(v.width, v.height, "--width/--height");
    // The same picture in more or fewer pixels: pixel lengths of the lens scale with the
    // height (angles and extents stay); a grid-aligned map takes the size as given.
    const double scale = static_cast<double>(v.height) / old_height;
    v.lens.fisheye_focal *= scale;
    v.lens.principal_x *= scale;
    v.lens.principal_y *= scale;
    if (width || height) v.has_size = true;
  }
}

void apply_render_choices(Scenario& s, const RenderChoices& c) {
  s.choices = c;
  if (c.spp) {
    if (*c.spp < 1 || *c.spp > kMaxSpp)
      throw InputError("spp " + std::to_string(*c.spp) + ": expected 1 to " +
                       std::to_string(kMaxSpp));
    s.render.spp = *c.spp;
  }
  if (c.threads) {
    if (*c.threads < 0 || *c.threads > 1024)
      throw InputError("threads " + std::to_string(*c.threads) +
                       ": expected 0 (every core) to 1024");
    s.render.threads = *c.threads;
  }
  override_view_sizes(s, c.width, c.height);
  if (c.view.empty()) return;
  std::string names;
  for (const ViewSettings& v : s.views) {
    if (v.name == c.view) {
      const ViewSettings chosen = v;
      s.views = {chosen};
      for (const ObjectSettings& o : s.objects)
        if (o.siting && o.siting->view != c.view)
          throw InputError(c.source + ": " + o.siting->location + ": [" + o.path +
                           ".place] places '" + o.name + "' by view \"" + o.siting->view +
                           "\", which " + c.source + " " + c.view + " leaves out: render both");
      return;
    }
    names += (names.empty() ? "" : ", ") + v.name;
  }
  throw InputError(c.source + ": no view named \"" + c.view + "\" in " + s.source +
                   " (views: " + names + ")");
}

}  // namespace landsim::scenes
