#include "generators/occupancy_image.h"

#include <png.h>
#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>

#include "core/printable.h"
#include "core/str_cat.h"
#include "core/text_file.h"

namespace agv {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void check_size(const std::string& name, long width, long height, int line) {
  // The one map size limit (core/grid.h), as for generated maps and MovingAI files.
  if (width < 1 || height < 1 || width > kMaxMapSide || height > kMaxMapSide)
    throw InputError(str_cat(name, ":", line, ": image size ", width, "x", height,
                             " is outside 1..", kMaxMapSide, " per side"));
}

// The PGM header's tokens (magic, width, height, maxval), '#' comments skipped, with the line
// each starts on; `pos` ends one past the last token.
class PgmHeader {
 public:
  PgmHeader(const std::string& data, const std::string& name) : data_(data), name_(name) {}

  long number(const char* what) {
    skip_space_and_comments();
    token_line_ = line_;
    const std::size_t start = pos_;
    while (pos_ < data_.size() && std::isdigit(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (pos_ == start || pos_ - start > 9)
      fail(str_cat("expected the ", what, " (a decimal number), found ",
                   pos_ < data_.size() ? str_cat("'", data_[start], "'") : std::string("the end")));
    return std::stol(data_.substr(start, pos_ - start));
  }
  void skip_space_and_comments() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        break;
      }
    }
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(str_cat(name_, ":", line_, ": ", what));
  }
  // At the end of the file: the line of the last token read, not the empty one after it.
  [[noreturn]] void fail_at_last_token(const std::string& what) const {
    throw InputError(str_cat(name_, ":", token_line_, ": ", what));
  }
  std::size_t& pos() { return pos_; }
  int& line() { return line_; }

 private:
  const std::string& data_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int token_line_ = 1;
};

}  // namespace

ImagePixels read_pgm(const std::string& path) {
  const std::string data = read_text_file(path, "PGM image", std::uintmax_t{1} << 31);
  PgmHeader h(data, path);
  if (data.size() < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5'))
    h.fail("not a PGM image (expected magic number P2 or P5)");
  const bool binary = data[1] == '5';
  h.pos() = 2;
  if (h.pos() < data.size() && !std::isspace(static_cast<unsigned char>(data[h.pos()])) &&
      data[h.pos()] != '#')
    h.fail("not a PGM image (expected white space after the magic number)");
  const long width = h.number("width");
  const long height = h.number("height");
  check_size(path, width, height, h.line());
  const long maxval = h.number("maximum value");
  if (maxval < 1 || maxval > 65535)
    h.fail(str_cat("maximum value ", maxval, " is outside 1..65535"));
  ImagePixels out;
  out.width = static_cast<int>(width);
  out.height = static_cast<int>(height);
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  out.grey.resize(n);
  const auto to_8bit = [maxval](long v) {
    return static_cast<unsigned char>(
        std::lround(static_cast<double>(v) * 255.0 / static_cast<double>(maxval)));
  };
  if (binary) {
    // Exactly one white-space byte separates the maximum value from the samples.
    if (h.pos() >= data.size() || !std::isspace(static_cast<unsigned char>(data[h.pos()])))
      h.fail("expected one white-space byte after the maximum value");
    const std::size_t start = h.pos() + 1;
    const std::size_t bytes = maxval < 256 ? 1 : 2;
    if (data.size() - start < n * bytes)
      h.fail(str_cat("the samples end after ", (data.size() - start) / bytes, " of ", width, "x",
                     height, " = ", n, " pixels"));
    for (std::size_t i = 0; i < n; ++i) {
      long v = static_cast<unsigned char>(data[start + i * bytes]);
      if (bytes == 2) v = v * 256 + static_cast<unsigned char>(data[start + i * bytes + 1]);
      if (v > maxval)
        throw InputError(str_cat(path, ": pixel ", i % width, ",", i / width, " is ", v,
                                 ", above the maximum value ", maxval));
      out.grey[i] = to_8bit(v);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      h.skip_space_and_comments();
      if (h.pos() >= data.size())
        h.fail_at_last_token(
            str_cat("the samples end after ", i, " of ", width, "x", height, " = ", n, " pixels"));
      const long v = h.number("pixel value");
      if (v > maxval) h.fail(str_cat("pixel value ", v, " is above the maximum value ", maxval));
      out.grey[i] = to_8bit(v);
    }
    h.skip_space_and_comments();
    if (h.pos() < data.size()) h.fail("more samples than width x height");
  }
  return out;
}

ImagePixels read_png(const std::string& path) {
  require_regular_file(path, "PNG image");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  const auto failed = [&](const char* stage) {
    const std::string why = image.message;
    png_image_free(&image);
    return InputError(str_cat(path, ": not a readable PNG image (", stage, ": ", why, ")"));
  };
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0) throw failed("header");
  try {
    check_size(path, static_cast<long>(image.width), static_cast<long>(image.height), 1);
  } catch (const InputError&) {
    png_image_free(&image);
    throw;
  }
  const bool has_alpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  // 8-bit RGBA whatever the file holds: libpng converts grey, palette and 16-bit images.
  image.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> rgba;
  try {
    rgba.resize(PNG_IMAGE_SIZE(image));
  } catch (const std::bad_alloc&) {
    png_image_free(&image);
    throw;
  }
  if (png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr) == 0) throw failed("pixels");
  ImagePixels out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  out.grey.resize(n);
  if (has_alpha) out.alpha.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* p = &rgba[4 * i];
    // map_server averages the colour channels (it does not weight them as luminance).
    out.grey[i] = static_cast<unsigned char>((p[0] + p[1] + p[2] + 1) / 3);
    if (has_alpha) out.alpha[i] = p[3];
  }
  png_image_free(&image);
  return out;
}

Grid occupancy_grid(const ImagePixels& pixels, const OccupancyThresholds& t, double cell_edge) {
  Grid grid(pixels.width, pixels.height, cell_edge);
  for (int y = 0; y < pixels.height; ++y) {
    for (int x = 0; x < pixels.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * pixels.width + x;
      const double grey = pixels.grey[i];
      const double p = t.negate ? grey / 255.0 : (255.0 - grey) / 255.0;
      const bool transparent = t.scale && !pixels.alpha.empty() && pixels.alpha[i] < 255;
      const bool free = !transparent && p < t.free;
      // Occupied (p > occupied) and unknown (in between, or transparent) alike are not free.
      if (!free) grid.set_blocked(x, y, true);
    }
  }
  return grid;
}

namespace {

ImagePixels read_image(const std::string& path) {
  const std::string ext = lower_extension(path);
  // A few kilobytes of PNG can declare 8192x8192 pixels, about 400 MiB decoded: past what this
  // process may allocate, that is a runtime failure naming the file, not a bare bad_alloc.
  try {
    if (ext == ".pgm") return read_pgm(path);
    if (ext == ".png") return read_png(path);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(path +
                             ": decoding the image needs more memory than this process can "
                             "allocate (ulimit -v, the container's memory.max or the machine's)");
  }
  throw InputError(path + ": not an occupancy image this reader knows (.yaml, .pgm or .png)");
}

// A map_server .yaml: every key checked, each error naming the file and the key's line.
OccupancyImage read_yaml(const std::string& path) {
  const std::string text = read_text_file(path, "map description", std::uintmax_t{1} << 20);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(str_cat(path, ":", e.mark.line + 1, ": malformed YAML (", e.msg, ")"));
  }
  if (!root.IsMap()) throw InputError(str_cat(path, ":1: expected a map_server map description"));
  OccupancyThresholds t;
  std::string image;
  double resolution = 0.0;
  bool have_resolution = false;
  std::map<std::string, int>
      seen;  // key -> its line: YAML forbids a key twice, yaml-cpp keeps both
  for (const auto& kv : root) {
    const int line = kv.first.Mark().line + 1;
    std::string key;
    try {
      key = kv.first.as<std::string>();
      if (const auto [at, fresh] = seen.emplace(key, line); !fresh)
        throw InputError(str_cat(path, ":", line, ": ", printable(key),
                                 ": given twice (first at line ", at->second, ")"));
      const YAML::Node& v = kv.second;
      const auto number = [&](double lo, double hi) {
        const double x = v.as<double>();
        if (!std::isfinite(x) || x < lo || x > hi)
          throw InputError(
              str_cat(path, ":", line, ": ", key, ": ", x, " is outside [", lo, ", ", hi, "]"));
        return x;
      };
      if (key == "image") {
        image = v.as<std::string>();
      } else if (key == "resolution") {
        resolution = number(1e-9, 1e9);
        if (resolution <= 0.0)
          throw InputError(str_cat(path, ":", line, ": resolution: must be positive"));
        have_resolution = true;
      } else if (key == "origin") {
        if (!v.IsSequence() || v.size() != 3)
          throw InputError(str_cat(path, ":", line, ": origin: expected [x, y, yaw]"));
        for (const auto& c : v) (void)c.as<double>();
      } else if (key == "negate") {
        const std::string s = v.as<std::string>();
        if (s == "0" || s == "false") {
          t.negate = false;
        } else if (s == "1" || s == "true") {
          t.negate = true;
        } else {
          throw InputError(str_cat(path, ":", line, ": negate: expected 0 or 1, got \"", s, "\""));
        }
      } else if (key == "occupied_thresh") {
        t.occupied = number(0.0, 1.0);
      } else if (key == "free_thresh") {
        t.free = number(0.0, 1.0);
      } else if (key == "mode") {
        const std::string mode = v.as<std::string>();
        if (mode == "trinary") {
          t.scale = false;
        } else if (mode == "scale") {
          t.scale = true;
        } else {
          throw InputError(str_cat(path, ":", line, ": mode: \"", mode,
                                   "\" is not one of: trinary, scale (raw values are not occupancy "
                                   "a grid planner can read)"));
        }
      } else {
        throw InputError(str_cat(path, ":", line, ": unknown key \"", key,
                                 "\" (known: image, resolution, origin, negate, occupied_thresh, "
                                 "free_thresh, mode)"));
      }
    } catch (const YAML::Exception& e) {
      throw InputError(str_cat(path, ":", line, ": ", key.empty() ? "key" : key, ": ", e.msg));
    }
  }
  if (image.empty()) throw InputError(str_cat(path, ":1: image: missing"));
  if (!have_resolution) throw InputError(str_cat(path, ":1: resolution: missing"));
  if (t.free > t.occupied)
    throw InputError(
        str_cat(path, ": free_thresh ", t.free, " is above occupied_thresh ", t.occupied));
  // A relative image path is relative to the .yaml's folder, as map_server reads it.
  std::filesystem::path image_path(image);
  if (image_path.is_relative()) image_path = std::filesystem::path(path).parent_path() / image_path;
  OccupancyImage out{occupancy_grid(read_image(image_path.string()), t, resolution), true,
                     image_path.string()};
  return out;
}

}  // namespace

OccupancyImage read_occupancy_image(const std::string& path, double cell_edge) {
  const std::string ext = lower_extension(path);
  if (ext == ".yaml" || ext == ".yml") return read_yaml(path);
  return {occupancy_grid(read_image(path), OccupancyThresholds{}, cell_edge), false, path};
}

}  // namespace agv
