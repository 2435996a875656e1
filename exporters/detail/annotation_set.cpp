#include "exporters/detail/annotation_set.h"

#include <fstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"

namespace landsim::exporters::detail {

std::map<std::uint32_t, TreeSeen> trees_in(const renderer::Film& film) {
  std::map<std::uint32_t, TreeSeen> out;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::uint32_t id = film.instance(x, y);
      if (id == renderer::kNoId) continue;
      TreeSeen& t = out[id];
      t.species = film.species(x, y);
      ++t.pixels;
      t.x0 = std::min(t.x0, x), t.y0 = std::min(t.y0, y);
      t.x1 = std::max(t.x1, x), t.y1 = std::max(t.y1, y);
    }
  return out;
}

std::string species_name(const json& legend, std::uint32_t species) {
  return legend.at("species").at("values").at(species).at("name").get<std::string>();
}

std::map<std::uint32_t, std::string> classes(const json& legend) {
  std::map<std::uint32_t, std::string> out;
  for (const json& v : legend.at("target").at("values"))
    out[v.at("id").get<std::uint32_t>()] =
        std::filesystem::path(v.at("file").get<std::string>()).stem().string();
  return out;
}

std::vector<ClassName> class_names(const json& manifest,
                                   const std::map<std::uint32_t, std::string>& objects,
                                   bool trees) {
  std::vector<ClassName> out;
  const auto add = [&](const std::string& name, const char* super) {
    for (const ClassName& c : out)
      if (c.name == name) return;
    out.push_back({name, super});
  };
  for (const auto& [id, name] : objects) add(name, "object");
  for (const json& image : manifest.at("images"))  // classes drawn per image ([randomise])
    for (const json& o : image.value("objects", json::array()))
      if (o.contains("class")) add(o.at("class").get<std::string>(), "object");
  if (trees)
    for (const json& sp : manifest.at("legend").at("species").at("values"))
      add(sp.at("name").get<std::string>(), "tree");
  return out;
}

std::string class_of(const json& object, const std::map<std::uint32_t, std::string>& legend) {
  if (object.contains("class")) return object.at("class").get<std::string>();
  return legend.at(object.at("target").get<std::uint32_t>());
}

bool annotated(const json& object, const AnnotationOptions& options) {
  return !object.at("bbox").is_null() &&
         object.at("visible_pixels").get<std::size_t>() >= options.min_pixels;
}

int occlusion_level(double visible_fraction) {
  return visible_fraction >= 0.9 ? 0 : visible_fraction >= 0.5 ? 1 : 2;
}

std::string stem_of(const json& image) {
  return std::filesystem::path(image.at("path").get<std::string>()).stem().string();
}

json image_file(const json& image, const std::filesystem::path& set,
                const AnnotationOptions& options) {
  if (options.image == AnnotationOptions::Image::exr) return image.at("path");
  if (options.image == AnnotationOptions::Image::preview) return image.at("preview");
  if (!image.contains("sensor") || !image.at("sensor").contains("path"))
    throw InputError((set / "manifest.json").string() + ": image " +
                     image.at("path").get<std::string>() +
                     " has no digital-number image (render the set with a [sensor])");
  return image.at("sensor").at("path");
}

namespace {
template <typename Inside>
std::vector<std::uint8_t> mask_where(const renderer::Film& film, Inside inside) {
  std::vector<std::uint8_t> mask(film.pixel_count());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      mask[static_cast<std::size_t>(y) * film.width() + x] = inside(x, y) ? 1 : 0;
  return mask;
}
}  // namespace

std::vector<std::uint8_t> target_mask(const renderer::Film& film, std::uint32_t target) {
  return mask_where(film, [&](int x, int y) { return film.target(x, y) == target; });
}

std::vector<std::uint8_t> instance_mask(const renderer::Film& film, std::uint32_t instance) {
  return mask_where(film, [&](int x, int y) { return film.instance(x, y) == instance; });
}

// The manifest's footprint_mask: COCO's uncompressed RLE (column-major runs, zeros first).
std::vector<std::uint8_t> footprint_mask(const json& object, int width, int height) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * height);
  std::size_t i = 0;  // column-major position
  std::uint8_t value = 0;
  for (const json& run : object.value("footprint_mask", json::array())) {
    const auto n = run.get<std::size_t>();
    if (n > mask.size() - i) throw std::out_of_range("footprint_mask runs past the image");
    for (std::size_t k = 0; k < n; ++k, ++i)
      if (value) mask[(i % height) * width + i / height] = 1;
    value ^= 1;
  }
  return mask;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  AtomicFile out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path.string());
  }
  out.commit();
}

std::map<std::string, int> write_yolo_classes(const json& manifest,
                                              const std::filesystem::path& out, bool trees) {
  std::map<std::string, int> index;
  std::string list;
  for (const ClassName& c : class_names(manifest, classes(manifest.at("legend")), trees)) {
    index.emplace(c.name, static_cast<int>(index.size()));
    list += c.name + "\n";
  }
  std::filesystem::create_directories(out);
  write_text(out / "classes.txt", list);
  return index;
}

}  // namespace landsim::exporters::detail
