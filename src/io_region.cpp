// Region reports: `fixel region --json` / `fixel sample --json` and text.
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/internal/json_approx.h"
#include "fixel/internal/readable.h"
#include "fixel/internal/scene_differs.h"
#include "fixel/io.h"

namespace fixel {

namespace {
using json = nlohmann::ordered_json;
}  // namespace

namespace {
json magnitudes_json(const RegionInterval& r) {
  if (r.status != RegionStatus::kIn || r.magnitudes.empty) return nullptr;
  const Magnitudes& m = r.magnitudes;
  return {{"min", to_string(m.lo)},
          {"min_inclusive", m.lo_closed},
          {"max", m.hi ? json(to_string(*m.hi)) : json(nullptr)},
          {"max_inclusive", m.hi.has_value() && m.hi_closed},
          {"approx", {to_double(m.lo), m.hi ? json(to_double(*m.hi)) : json(nullptr)}}};
}

// An end of an interval: "p/q", or for an irrational end of the exact
// region its minimal polynomial and isolating interval (docs/formats.md).
json end_json(const Rational& u, const std::optional<AlgebraicReal>& exact) {
  if (!exact) return to_string(u);
  json poly = json::array();
  for (const auto& c : exact->poly) poly.push_back(c.str());
  return {{"poly", poly}, {"isolating", {to_string(exact->lo), to_string(exact->hi)}}, {"approx", exact->approx()}};
}

// The same in text: exact when rational, else the certified decimal digits
// (at most `digits`, 15 when 0).
std::string end_text(const Rational& u, const std::optional<AlgebraicReal>& exact, int digits) {
  return exact ? certified_decimal(*exact, digits > 0 ? digits : 15) : to_string(u);
}

json point_json(const Vec2& p) { return json::array({to_string(p.x), to_string(p.y)}); }

// Arc length per status, m (display).
std::map<std::string, double> status_arc_lengths(const Region& region) {
  std::map<std::string, double> len{{"in", 0}, {"out", 0}, {"partial", 0}};
  for (std::size_t k = 0; k < region.intervals.size() && k < region.places.size(); ++k)
    len[to_string(region.intervals[k].status)] += region.places[k].arc_length;
  return len;
}

std::string percent(double part, double whole) {
  return whole > 0 ? internal::decimal(100 * part / whole, 3) + "%" : "n/a";
}

std::map<std::string, Rational> status_lengths(const Region& region) {
  std::map<std::string, Rational> len{{"in", 0}, {"out", 0}, {"partial", 0}};
  for (const auto& r : region.intervals) len[to_string(r.status)] += r.u1 - r.u0;
  return len;
}
}  // namespace

std::string region_json(const Scene& scene, const Region& region, const SeatedPose* seat) {
  internal::check_same_scene(region.built_from.get(), scene, internal::region_reads(region.target), "region");
  json doc;
  doc["scene"] = scene.name;
  doc["method"] = method_of(region);
  doc["resolution"] = region.resolution ? json(to_string(*region.resolution)) : json(nullptr);
  if (region.resolution_length) {
    doc["resolution_length"] = to_string(*region.resolution_length);
    json widths = json::array();
    for (const auto& w : region.piece_widths) widths.push_back(to_string(w));
    doc["piece_widths"] = widths;
  }
  doc["pusher_mu"] = to_string(region.pusher_mu);
  doc["target"] = region.target;
  doc["meaning"] = {{"in", in_meaning(region)}, {"physics", "docs/physics.md"}};
  doc["intervals"] = json::array();
  std::map<std::string, int> counts{{"in", 0}, {"out", 0}, {"partial", 0}};
  for (std::size_t k = 0; k < region.intervals.size(); ++k) {
    const RegionInterval& r = region.intervals[k];
    ++counts[to_string(r.status)];
    doc["intervals"].push_back({{"curve", r.curve},
                                {"u0", end_json(r.u0, r.exact_u0)},
                                {"u1", end_json(r.u1, r.exact_u1)},
                                {"status", to_string(r.status)},
                                {"half_line", r.half_line},
                                {"magnitudes", magnitudes_json(r)}});
    if (k < region.places.size()) {
      const IntervalPlace& at = region.places[k];
      json& j = doc["intervals"].back();
      j["start"] = point_json(at.start_A);
      j["end"] = point_json(at.end_A);
      j["arc_length"] = at.arc_length;
      j["push_direction"] =
          at.push_direction_A
              ? json::array({(*at.push_direction_A)[0] + 0.0, (*at.push_direction_A)[1] + 0.0})  // -0.0 shown as 0.0
              : json(nullptr);
    }
    if (!r.magnitude_set.empty()) {
      json set = json::array();
      for (const auto& m : r.magnitude_set) {
        RegionInterval one = r;
        one.magnitudes = m;
        set.push_back(magnitudes_json(one));
      }
      doc["intervals"].back()["magnitude_intervals"] = set;
    }
  }
  if (!region.sampled) {
    doc["corners"] = json::array();
    for (const RegionCorner& c : region.corners)
      doc["corners"].push_back({{"curve", c.curve}, {"u", to_string(c.u)}, {"status", to_string(c.status)}});
  }
  doc["counts"] = counts;
  if (region.sampled) {
    // Sample points have no length: the summary counts them ("counts" above
    // is per status, one interval per point).
    doc["points"] = region.intervals.size();
  } else {
    json lengths;
    for (const auto& [k, v] : status_lengths(region)) lengths[k] = to_string(v);
    doc["lengths"] = lengths;
    json arc = {{"outline", region.outline_length}};
    for (const auto& [k, v] : status_arc_lengths(region)) arc[k] = v;
    doc["arc_lengths"] = arc;
  }
  doc["stats"] = {{"cone_tests", region.stats.cone_tests},
                  {"lp_tests", region.stats.lp_tests},
                  {"point_tests", region.stats.point_tests},
                  {"depth", region.stats.depth}};
  if (!region.sampled) doc["stats"]["partial_length"] = to_string(region.stats.partial_length);
  doc["stats"]["seconds"] = region.stats.seconds;
  if (region.exact) {
    doc["stats"]["roots"] = region.stats.roots;
    doc["exact"] = true;
    doc["digits"] = region.digits;
    bool irrational_end = false;
    for (const auto& r : region.intervals) irrational_end = irrational_end || r.exact_u0 || r.exact_u1;
    doc["lengths_exact"] = !irrational_end;  // else "lengths" sums the isolating midpoints
  }
  if (seat) {
    doc["seated_pose"] = json::parse(seated_pose_json(*seat));
    std::string note = seat_rotation_note(*seat);
    if (!note.empty() && note.back() == '\n') note.pop_back();
    doc["seat_note"] = note;
  }
  if (region.push != "step") doc["push"] = region.push;
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

std::string region_text(const Scene& scene, const Region& region) {
  internal::check_same_scene(region.built_from.get(), scene, internal::region_reads(region.target), "region");
  std::ostringstream out;
  const bool sustained = region.push == "sustained";
  const std::string meaning = in_meaning(region);
  out << "Pushing region of scene \"" << scene.name << "\" (" << (sustained ? "sustained push, " : "")
      << method_of(region);
  if (region.exact)
    out << ": root isolation" << (region.digits ? ", digits " + std::to_string(region.digits) : "");
  else if (region.resolution)
    out << ", resolution " << to_string(*region.resolution) << " of curve parameter";
  else if (region.resolution_length)
    out << ", resolution length " << internal::readable(*region.resolution_length)
        << " m (each sub-piece left partial is at most this long)";
  out << ", pusher mu " << to_string(region.pusher_mu) << ")\n";
  out << "  IN means \"" << meaning << "\""
      << (region.target == "S"   ? ": some outcome of the one-step model seats"
          : region.target == "G" ? ": every outcome of the one-step model seats"
          : region.target == "J" ? ": the held push drives the part into its seat (in the model linearised there)"
                                 : ": the held push drives the part into its seat (in the model linearised there), and "
                                   "no pair of fixels can hold it at any two-contact pose on the way")
      << "; what it is worth in a physics engine: docs/physics.md\n";
  out << "  each line: curve and parameter span, status, where it is on the part (m, frame A), outline length, the "
         "frictionless push direction\n";
  if (region.exact)
    out << "  exact ends: each status holds strictly between its ends; an end's own status is not decided "
           "(push-plan --at K:U tests a rational one)\n";
  for (std::size_t k = 0; k < region.intervals.size(); ++k) {
    const RegionInterval& r = region.intervals[k];
    out << "  curve " << r.curve << "  u in [" << end_text(r.u0, r.exact_u0, region.digits) << ", "
        << end_text(r.u1, r.exact_u1, region.digits) << "]  ";
    out << (r.status == RegionStatus::kIn ? "IN     " : r.status == RegionStatus::kOut ? "out    " : "partial");
    if (k < region.places.size()) {
      const IntervalPlace& at = region.places[k];
      auto xy = [](const Vec2& p) {
        return "(" + internal::decimal(to_double(p.x), 4) + ", " + internal::decimal(to_double(p.y), 4) + ")";
      };
      out << "  " << (r.u0 == r.u1 ? "at " + xy(at.start_A) : xy(at.start_A) + " to " + xy(at.end_A));
      if (r.u0 != r.u1) out << ", " << internal::decimal(at.arc_length, 3) << " m";
      if (r.status == RegionStatus::kIn && at.push_direction_A)
        out << ", push along (" << internal::decimal((*at.push_direction_A)[0], 3) << ", "
            << internal::decimal((*at.push_direction_A)[1], 3) << ")";
    }
    if (r.status == RegionStatus::kIn) {
      out << "  [" << meaning << "]" << (r.half_line ? " half-line" : "");
      if (sustained)
        out << ", any magnitude";
      else if (region.exact)
        out << ", magnitudes not computed with --exact";
      else if (!r.magnitudes.empty)
        out << ", |p| in " << r.magnitudes.describe_readable() << " N*s";
      else
        out << ", no common magnitude";
    }
    out << "\n";
  }
  if (!region.corners.empty()) {
    out << "  at these corners an interval ends whose status is not the corner's own (the corner's holds for its "
           "whole fan of pushes, the interval's for its own edge's normal):";
    for (std::size_t k = 0; k < region.corners.size(); ++k) {
      const RegionCorner& c = region.corners[k];
      out << (k == 0 ? " " : ", ") << "curve " << c.curve << " u=" << to_string(c.u) << " " << to_string(c.status);
    }
    out << "\n";
  }
  if (region.sampled) {
    std::map<std::string, std::size_t> points{{"in", 0}, {"out", 0}, {"partial", 0}};
    for (const auto& r : region.intervals) ++points[to_string(r.status)];
    out << region.intervals.size() << " sample point(s): IN (" << meaning << ") " << points.at("in") << ", out "
        << points.at("out") << ", partial " << points.at("partial") << " (point tests say nothing between points)\n";
  } else {
    const auto arc = status_arc_lengths(region);
    bool irrational_end = false;
    for (const auto& r : region.intervals) irrational_end = irrational_end || r.exact_u0 || r.exact_u1;
    out << "outline " << internal::decimal(region.outline_length, 4) << " m: IN (" << meaning << ") "
        << percent(arc.at("in"), region.outline_length) << ", out " << percent(arc.at("out"), region.outline_length)
        << ", partial " << percent(arc.at("partial"), region.outline_length) << " of its arc length ("
        << (irrational_end ? "parameter lengths, from the isolating midpoints of irrational ends: --json \"lengths\""
                           : "exact parameter lengths: --json \"lengths\"")
        << ")\n";
  }
  out << "cone tests " << region.stats.cone_tests << ", LP tests " << region.stats.lp_tests << ", point tests "
      << region.stats.point_tests << ", depth " << region.stats.depth;
  if (region.exact) out << ", roots " << region.stats.roots;
  out << ", " << region.stats.seconds << " s\n";
  return out.str();
}

}  // namespace fixel
