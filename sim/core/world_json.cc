// Reading a world file: JSON -> World, with every mistake reported as "FILE: FIELD: problem".
#include "core/world.h"

#include "bounded_file.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace carbot {
namespace {

using nlohmann::json;

/// Walks a JSON document and knows the dotted path of the value it looks at, so that every
/// error names its field the way a person would write it: `line.points[3]`.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw WorldError(fmt::format("{}: {}: {}", file_, field, what));
  }

  static std::string member(const std::string& field, const char* key) {
    return field.empty() ? key : field + "." + key;
  }
  static std::string index(const std::string& field, size_t i) { return fmt::format("{}[{}]", field, i); }

  double number(const json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d)) fail(field, "expected a finite number");
    // Metres, degrees and seconds: past a million of any, a world is a mistake or an attack,
    // and the physics (ODE asserts on a heading of 1e308) would not survive it.
    if (std::fabs(d) > kMaxMagnitude)
      fail(field, fmt::format("expected a number between -{0:g} and {0:g}, got {1:g}", kMaxMagnitude, d));
    return d;
  }

  static constexpr double kMaxMagnitude = 1e6;

  double positive(const json& v, const std::string& field) const {
    double d = number(v, field);
    if (d <= 0) fail(field, fmt::format("expected a positive number, got {}", d));
    return d;
  }

  Vec2 pair(const json& v, const std::string& field, const char* shape = "[x, y]") const {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      fail(field, fmt::format("expected {}", shape));
    return {number(v[0], index(field, 0)), number(v[1], index(field, 1))};
  }

  std::string text(const json& v, const std::string& field) const {
    if (!v.is_string() || v.get<std::string>().empty()) fail(field, "expected a non-empty string");
    return v.get<std::string>();
  }

  const json& array(const json& v, const std::string& field) const {
    if (!v.is_array()) fail(field, "expected an array");
    return v;
  }

  /// Requires an object whose keys are all in `known`; a typo gets named, not ignored.
  const json& object(const json& v, const std::string& field, std::initializer_list<const char*> known) const {
    if (!v.is_object()) fail(field.empty() ? "(top level)" : field, "expected an object");
    for (auto it = v.begin(); it != v.end(); ++it) {
      bool ok = false;
      for (const char* k : known) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : known) list += fmt::format("{}{}", list.empty() ? "" : ", ", k);
        fail(member(field, it.key().c_str()), fmt::format("unknown field (expected one of: {})", list));
      }
    }
    return v;
  }

  const json* find(const json& obj, const char* key) const {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  const json& require(const json& obj, const std::string& field, const char* key) const {
    const json* v = find(obj, key);
    if (!v) fail(member(field, key), "missing");
    return *v;
  }

 private:
  std::string file_;
};

Line read_line(const Reader& r, const json& v) {
  const std::string f = "line";
  r.object(v, f, {"width", "closed", "points"});
  Line line;
  if (const json* w = r.find(v, "width")) line.width = r.positive(*w, f + ".width");
  if (const json* c = r.find(v, "closed")) {
    if (!c->is_boolean()) r.fail(f + ".closed", "expected true or false");
    line.closed = c->get<bool>();
  }
  const json& pts = r.array(r.require(v, f, "points"), f + ".points");
  if (pts.size() > kMaxLinePoints)
    r.fail(f + ".points", fmt::format("expected at most {} points, got {}", kMaxLinePoints, pts.size()));
  for (size_t i = 0; i < pts.size(); ++i) line.points.push_back(r.pair(pts[i], Reader::index(f + ".points", i)));
  if (line.points.size() < 2) r.fail(f + ".points", "expected at least 2 points");
  for (size_t i = 1; i < line.points.size(); ++i) {
    const Vec2 a = line.points[i - 1], b = line.points[i];
    if (a.x == b.x && a.y == b.y) r.fail(Reader::index(f + ".points", i), "repeats the previous point");
  }
  return line;
}

Wall read_wall(const Reader& r, const json& v, const std::string& f) {
  r.object(v, f, {"from", "to", "thickness", "height"});
  Wall w;
  w.from = r.pair(r.require(v, f, "from"), f + ".from");
  w.to = r.pair(r.require(v, f, "to"), f + ".to");
  if (w.from.x == w.to.x && w.from.y == w.to.y) r.fail(f + ".to", "equals 'from': a wall needs a length");
  if (const json* t = r.find(v, "thickness")) w.thickness = r.positive(*t, f + ".thickness");
  if (const json* h = r.find(v, "height")) w.height = r.positive(*h, f + ".height");
  return w;
}

Box read_box(const Reader& r, const json& v, const std::string& f) {
  r.object(v, f, {"center", "size", "height"});
  Box b;
  b.center = r.pair(r.require(v, f, "center"), f + ".center");
  b.size = r.pair(r.require(v, f, "size"), f + ".size", "[w, d] (metres)");
  if (b.size.x <= 0 || b.size.y <= 0) r.fail(f + ".size", "expected positive [w, d]");
  if (const json* h = r.find(v, "height")) b.height = r.positive(*h, f + ".height");
  return b;
}

Item read_item(const Reader& r, const json& v, const std::string& f) {
  r.object(v, f, {"name", "at", "destination"});
  Item it;
  it.name = r.text(r.require(v, f, "name"), f + ".name");
  it.at = r.pair(r.require(v, f, "at"), f + ".at");
  it.destination = r.pair(r.require(v, f, "destination"), f + ".destination");
  return it;
}

Event read_event(const Reader& r, const json& v, const std::string& f, const World& w) {
  r.object(v, f, {"at", "press", "drop", "to"});
  Event e;
  e.at = r.number(r.require(v, f, "at"), f + ".at");
  if (e.at < 0) r.fail(f + ".at", "expected a time >= 0 (seconds)");
  const json* press = r.find(v, "press");
  const json* drop = r.find(v, "drop");
  if ((press != nullptr) == (drop != nullptr)) r.fail(f, "expected exactly one of \"press\" or \"drop\"");
  if (press) {
    if (r.text(*press, f + ".press") != "escape") r.fail(f + ".press", "expected \"escape\" (the only button)");
    if (r.find(v, "to")) r.fail(f + ".to", "only a \"drop\" event has a landing point");
    e.kind = Event::Kind::PressEscape;
    return e;
  }
  e.kind = Event::Kind::DropItem;
  e.item = r.text(*drop, f + ".drop");
  bool known = false;
  for (const Item& it : w.items) known = known || it.name == e.item;
  if (!known) r.fail(f + ".drop", fmt::format("no item named '{}' in \"items\"", e.item));
  if (const json* to = r.find(v, "to")) {
    e.has_to = true;
    e.to = r.pair(*to, f + ".to");
  }
  return e;
}

Start read_start(const Reader& r, const json& v, const std::string& f) {
  r.object(v, f, {"pose"});
  const json& pose = r.require(v, f, "pose");
  if (!pose.is_array() || pose.size() != 3) r.fail(f + ".pose", "expected [x, y, heading_deg]");
  Start s;
  s.position = {r.number(pose[0], f + ".pose[0]"), r.number(pose[1], f + ".pose[1]")};
  s.heading_deg = r.number(pose[2], f + ".pose[2]");
  return s;
}

/// Turns a parse error's byte offset into "line L, column C" of the text.
std::string where(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, col = 1;
    else ++col;
  }
  return fmt::format("{}:{}", line, col);
}

std::string stem(const std::string& path) {
  size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  size_t dot = base.rfind('.');
  return dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);
}

}  // namespace

World parse_world(const std::string& text, const std::string& path) {
  json doc;
  // A key given twice in one object would silently keep the last: refused, naming the key.
  std::vector<std::set<std::string>> keys;  // the keys seen, per open object
  std::string duplicate;
  auto callback = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    else if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    else if (event == json::parse_event_t::key && !keys.empty() && duplicate.empty()) {
      std::string key = parsed.get<std::string>();
      if (!keys.back().insert(key).second) duplicate = std::move(key);
    }
    return true;
  };
  try {
    doc = json::parse(text, callback);
  } catch (const json::parse_error& e) {
    std::string msg = e.what();
    size_t cut = msg.find("syntax error");  // drop nlohmann's "[json.exception...] parse error at..." prefix
    throw WorldError(fmt::format("{}:{}: not valid JSON: {}", path, where(text, e.byte ? e.byte - 1 : 0),
                                 cut == std::string::npos ? msg : msg.substr(cut)));
  } catch (const json::exception& e) {
    // e.g. a number too large for a double (1e309): nlohmann reports it as out_of_range.
    std::string msg = e.what();
    size_t cut = msg.find("] ");
    throw WorldError(
        fmt::format("{}: not a usable JSON document: {}", path, cut == std::string::npos ? msg : msg.substr(cut + 2)));
  }
  if (!duplicate.empty())
    throw WorldError(fmt::format("{}: {}: the key is given twice in one object", path, duplicate));
  Reader r(path);
  r.object(doc, "", {"description", "size", "line", "walls", "boxes", "items", "start", "events"});

  World w;
  w.path = path;
  w.name = stem(path);
  if (const json* d = r.find(doc, "description")) r.text(*d, "description");
  w.size = r.pair(r.require(doc, "", "size"), "size", "[w, h] (metres)");
  if (w.size.x <= 0 || w.size.y <= 0) r.fail("size", "expected positive [w, h]");
  if (const json* v = r.find(doc, "line")) w.line = read_line(r, *v);
  // The run's cost grows with the obstacles: counted before any is read.
  std::size_t obstacles = 0;
  for (const char* key : {"walls", "boxes", "items"})
    if (const json* v = r.find(doc, key)) {
      r.array(*v, key);
      obstacles += v->size();
      if (obstacles > kMaxWorldObstacles)
        r.fail(key, fmt::format("a world holds at most {} walls, boxes and items in all; this one has at least {}",
                                kMaxWorldObstacles, obstacles));
    }
  if (const json* v = r.find(doc, "walls")) {
    r.array(*v, "walls");
    for (size_t i = 0; i < v->size(); ++i) w.walls.push_back(read_wall(r, (*v)[i], Reader::index("walls", i)));
  }
  if (const json* v = r.find(doc, "boxes")) {
    r.array(*v, "boxes");
    for (size_t i = 0; i < v->size(); ++i) w.boxes.push_back(read_box(r, (*v)[i], Reader::index("boxes", i)));
  }
  if (const json* v = r.find(doc, "items")) {
    r.array(*v, "items");
    for (size_t i = 0; i < v->size(); ++i) {
      w.items.push_back(read_item(r, (*v)[i], Reader::index("items", i)));
      for (size_t j = 0; j < i; ++j)
        if (w.items[j].name == w.items[i].name)
          r.fail(Reader::index("items", i) + ".name",
                 fmt::format("'{}' is already used by items[{}]", w.items[i].name, j));
    }
  }
  // "start" is one robot's {pose} or, for several robots in one world, an array of them.
  const json& start = r.require(doc, "", "start");
  if (start.is_array()) {
    if (start.empty()) r.fail("start", "expected at least one robot");
    if (start.size() > static_cast<size_t>(kMaxRobots))
      r.fail("start", fmt::format("expected at most {} robots, got {}", kMaxRobots, start.size()));
    for (size_t i = 0; i < start.size(); ++i) w.robots.push_back(read_start(r, start[i], Reader::index("start", i)));
  } else {
    w.robots.push_back(read_start(r, start, "start"));
  }
  w.start = w.robots.front();
  if (const json* v = r.find(doc, "events")) {
    r.array(*v, "events");
    if (v->size() > kMaxWorldEvents)
      r.fail("events", fmt::format("expected at most {} events, got {}", kMaxWorldEvents, v->size()));
    for (size_t i = 0; i < v->size(); ++i) w.events.push_back(read_event(r, (*v)[i], Reader::index("events", i), w));
  }
  return w;
}

World load_world(const std::string& path) {
  // Only a regular file, opened without blocking and read to a bound: a FIFO, /dev/zero or a
  // huge file is an error, not a hang or gigabytes (docs/security.md).
  gfec::bounded_file::Text file = gfec::bounded_file::read(path, kMaxWorldBytes);
  if (file.too_large)
    throw WorldError(fmt::format("{}: cannot read the world file: larger than {}, the most a world may be", path,
                                 gfec::bounded_file::mib(kMaxWorldBytes)));
  if (!file.text) throw WorldError(fmt::format("{}: cannot read the world file: {}", path, file.why));
  return parse_world(*file.text, path);
}

}  // namespace carbot
