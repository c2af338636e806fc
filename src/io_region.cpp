// Region reports: `fixel region --json` / `fixel sample --json` and text.
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

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

std::map<std::string, Rational> status_lengths(const Region& region) {
  std::map<std::string, Rational> len{{"in", 0}, {"out", 0}, {"partial", 0}};
  for (const auto& r : region.intervals) len[to_string(r.status)] += r.u1 - r.u0;
  return len;
}
}  // namespace

std::string region_json(const Scene& scene, const Region& region) {
  json doc;
  doc["scene"] = scene.name;
  doc["method"] = method_of(region);
  doc["resolution"] = region.resolution ? json(to_string(*region.resolution)) : json(nullptr);
  doc["pusher_mu"] = to_string(region.pusher_mu);
  doc["intervals"] = json::array();
  std::map<std::string, int> counts{{"in", 0}, {"out", 0}, {"partial", 0}};
  for (const auto& r : region.intervals) {
    ++counts[to_string(r.status)];
    doc["intervals"].push_back({{"curve", r.curve},
                                {"u0", to_string(r.u0)},
                                {"u1", to_string(r.u1)},
                                {"status", to_string(r.status)},
                                {"half_line", r.half_line},
                                {"magnitudes", magnitudes_json(r)}});
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
  doc["counts"] = counts;
  json lengths;
  for (const auto& [k, v] : status_lengths(region)) lengths[k] = to_string(v);
  doc["lengths"] = lengths;
  doc["stats"] = {{"cone_tests", region.stats.cone_tests},
                  {"lp_tests", region.stats.lp_tests},
                  {"point_tests", region.stats.point_tests},
                  {"depth", region.stats.depth},
                  {"partial_length", to_string(region.stats.partial_length)},
                  {"seconds", region.stats.seconds}};
  if (region.push != "step") doc["push"] = region.push;
  return doc.dump(2) + "\n";
}

std::string region_text(const Scene& scene, const Region& region) {
  std::ostringstream out;
  const bool sustained = region.push == "sustained";
  out << "Pushing region of scene \"" << scene.name << "\" (" << (sustained ? "sustained push, " : "")
      << method_of(region);
  if (region.resolution) out << ", resolution " << to_string(*region.resolution);
  out << ", pusher mu " << to_string(region.pusher_mu) << ")\n";
  for (const auto& r : region.intervals) {
    out << "  curve " << r.curve << "  u in [" << to_string(r.u0) << ", " << to_string(r.u1) << "]  ";
    out << (r.status == RegionStatus::kIn ? "IN     " : r.status == RegionStatus::kOut ? "out    " : "partial");
    if (r.status == RegionStatus::kIn) {
      out << (r.half_line ? "  half-line" : "");
      if (sustained)
        out << "  any magnitude (sustained push: seats and stays)";
      else if (!r.magnitudes.empty)
        out << "  |p| in " << r.magnitudes.describe() << " N*s";
      else
        out << "  no common magnitude";
    }
    out << "\n";
  }
  const auto len = status_lengths(region);
  out << "parameter length: in " << to_string(len.at("in")) << ", out " << to_string(len.at("out")) << ", partial "
      << to_string(len.at("partial")) << "\n";
  out << "cone tests " << region.stats.cone_tests << ", LP tests " << region.stats.lp_tests << ", point tests "
      << region.stats.point_tests << ", depth " << region.stats.depth << ", " << region.stats.seconds << " s\n";
  return out.str();
}

}  // namespace fixel
