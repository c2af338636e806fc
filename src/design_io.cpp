// Fixture design input and output: the candidate file, `fixel design --json`,
// the text report and the SVG of the best layouts (docs/design.md).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/curve.h"
#include "fixel/design.h"
#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/json_exact.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

json pair_json(const Vec2& v) { return json::array({to_string(v.x), to_string(v.y)}); }

json candidate_json(const DesignCandidate& c) {
  return {{"curve", c.curve}, {"u", to_string(c.u)}, {"point", pair_json(c.point)}, {"normal", pair_json(c.normal)}};
}

json opt_rational(const std::optional<Rational>& q) { return q ? json(to_string(*q)) : json(nullptr); }

json finite(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json layout_json(const DesignResult& r, const DesignLayout& l, int rank) {
  json fixels = json::array();
  for (int i : l.fixels) fixels.push_back(candidate_json(r.candidates.at(i)));
  json j = {{"rank", rank},
            {"triple", json::array({l.fixels[0], l.fixels[1], l.fixels[2]})},
            {"index", l.index},
            {"fixels", fixels},
            {"score", to_string(l.score)},
            {"score_approx", to_double(l.score)},
            {"sustained_empty", l.sustained_empty ? json(*l.sustained_empty) : json(nullptr)},
            {"sustained_score", opt_rational(l.sustained_score)},
            {"step_score", opt_rational(l.step_score)},
            {"j_width", finite(l.j_width)},
            {"normal_angle_error", finite(l.normal_angle_error)},
            {"conditioning", finite(l.conditioning)},
            {"nearly_singular", std::isfinite(l.conditioning) ? json(l.conditioning < kNearlySingular) : json(nullptr)},
            {"curved_contacts", l.curved_contacts >= 0 ? json(l.curved_contacts) : json(nullptr)},
            {"step_seat", l.step_seat.empty() ? json(nullptr) : json(l.step_seat)}};
  if (!l.note.empty()) j["note"] = l.note;
  return j;
}

json shipped_json(const DesignLayout& l) {
  json j = {{"score", to_string(l.score)},
            {"score_approx", to_double(l.score)},
            {"sustained_empty", l.sustained_empty ? json(*l.sustained_empty) : json(nullptr)},
            {"sustained_score", opt_rational(l.sustained_score)},
            {"step_score", opt_rational(l.step_score)},
            {"j_width", finite(l.j_width)},
            {"conditioning", finite(l.conditioning)}};
  if (!l.note.empty()) j["note"] = l.note;
  return j;
}

// Two significant digits (display).
std::string significant(double x) {
  std::ostringstream s;
  s << std::setprecision(2) << x;
  return s.str();
}

const char* push_name(const DesignOptions& o) { return o.push == DesignPush::kSustained ? "sustained" : "step"; }

std::string mu_text(const DesignOptions& o) {
  return o.mu_hi ? "[" + to_string(o.mu) + ", " + to_string(*o.mu_hi) + "]" : to_string(o.mu);
}

std::string score_text(const std::optional<Rational>& q) {
  if (!q) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << to_double(*q) << " (" << to_string(*q) << ")";
  return s.str();
}

}  // namespace

std::vector<DesignCandidate> parse_candidates(const Scene& part, const std::string& json_text,
                                              const std::string& source) {
  const auto doc = internal::parse_json_exact(json_text, source);
  if (!doc.is_object() || !doc.contains("candidates"))
    throw ParseError("candidates", source, "must be an object {\"candidates\": [{\"curve\": k, \"u\": \"..\"}, ...]}");
  for (const auto& [key, value] : doc.items())
    if (key != "candidates") throw ParseError(key, value.dump().substr(0, 80), "is not a field of a candidate file");
  const auto& list = doc.at("candidates");
  if (!list.is_array()) throw ParseError("candidates", list.dump(), "must be an array");
  if (list.size() > 10000)
    throw InputError("candidates", std::to_string(list.size()) + " entries", "is more than 10000");
  std::vector<DesignCandidate> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string field = "candidates[" + std::to_string(i) + "]";
    const auto& e = list[i];
    if (!e.is_object() || !e.contains("curve") || !e.contains("u"))
      throw ParseError(field, e.dump(), "must be {\"curve\": k, \"u\": \"..\"}");
    for (const auto& [key, value] : e.items())
      if (key != "curve" && key != "u") throw ParseError(field + "." + key, value.dump(), "is not a candidate field");
    // Numbers arrive as their exact source text (parse_json_exact).
    const auto& c = e.at("curve");
    if (!c.is_string()) throw ParseError(field + ".curve", c.dump(), "must be a curve index");
    const Rational k = parse_rational(c.get<std::string>(), field + ".curve");
    if (boost::multiprecision::denominator(k) != 1 || k < 0 || k > 1000000)
      throw InputError(field + ".curve", c.get<std::string>(), "must be a curve index (an integer >= 0)");
    const auto& u = e.at("u");
    if (!u.is_string()) throw ParseError(field + ".u", u.dump(), "must be an exact number");
    out.push_back(candidate_at(part, static_cast<int>(boost::multiprecision::numerator(k).convert_to<long>()),
                               parse_rational(u.get<std::string>(), field + ".u"), field));
  }
  check_candidate_list(out);
  return out;
}

std::vector<DesignCandidate> load_candidates(const Scene& part, const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw InputError(path, "", "is a directory, not a candidate file");
  if (path == "-")  // not standard input: the part may already have used it
    throw InputError("load_candidates(path)", "-", "must name a candidate file (standard input is not read here)");
  errno = 0;
  std::ifstream in(path);
  if (!in) {
    const int reason = errno;  // the open's (ENOENT, EACCES, ...), when the library set it
    throw InputError(path, "",
                     std::string("cannot be opened") + (reason ? std::string(": ") + std::strerror(reason) : ""));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_candidates(part, buffer.str(), path);
}

std::string design_json(const Scene& part, const DesignResult& r, const DesignOptions& o,
                        const std::optional<DesignLayout>& shipped) {
  json doc;
  doc["part"] = part.name;
  doc["push"] = push_name(o);
  doc["resolution"] = to_string(o.resolution);
  doc["mu"] = o.mu_hi ? json::array({to_string(o.mu), to_string(*o.mu_hi)}) : json(to_string(o.mu));
  doc["pusher_mu"] =
      o.pusher_mu_lo ? json::array({to_string(*o.pusher_mu_lo), to_string(o.pusher_mu)}) : json(to_string(o.pusher_mu));
  doc["gap"] = to_string(o.gap);
  doc["candidates"] = json::array();
  for (const auto& c : r.candidates) doc["candidates"].push_back(candidate_json(c));
  doc["layouts"] = json::array();
  for (std::size_t k = 0; k < r.layouts.size(); ++k)
    doc["layouts"].push_back(layout_json(r, r.layouts[k], static_cast<int>(k) + 1));
  doc["no_layout"] = r.no_layout.empty() ? json(nullptr) : json(r.no_layout);
  doc["shipped"] = shipped ? shipped_json(*shipped) : json(nullptr);
  doc["stats"] = {{"candidates", r.stats.candidates},
                  {"triples", r.stats.triples},
                  {"pruned", r.stats.pruned()},
                  {"singular", r.stats.singular},
                  {"no_form_closure", r.stats.no_form_closure},
                  {"j_empty", r.stats.j_empty},
                  {"regions", r.stats.regions},
                  {"bounded", r.stats.bounded},
                  {"jobs", r.stats.jobs},
                  {"seconds", r.stats.seconds}};
  return doc.dump(1) + "\n";
}

std::string design_text(const Scene& part, const DesignResult& r, const DesignOptions& o,
                        const std::optional<DesignLayout>& shipped) {
  std::ostringstream s;
  s << "part " << part.name << ": " << r.stats.candidates << " candidates, " << r.stats.triples << " triples\n";
  s << "push " << push_name(o) << ", resolution " << to_string(o.resolution) << ", fixel mu " << mu_text(o)
    << ", pusher mu "
    << (o.pusher_mu_lo
            ? "[" + to_string(*o.pusher_mu_lo) + ", " + to_string(o.pusher_mu) + "] (judged at the upper end)"
            : to_string(o.pusher_mu))
    << ", gap " << to_string(o.gap) << " (one-step score)\n";
  const DesignStats& c = r.stats;
  // With the bound, the counts after "singular" are of the triples scored;
  // the singular ones are never scored.
  const std::string of_scored =
      c.bounded ? " of the " + std::to_string(c.no_form_closure + c.j_empty + c.regions) + " scored" : "";
  s << "dropped: " << c.singular << " with W_n singular (never scored), " << c.no_form_closure << of_scored
    << " without form closure, " << c.j_empty << " with J empty (score 0, no region); " << c.regions
    << " regions computed; ";
  if (c.bounded) s << c.bounded << " never scored (pair bound below the K-th score); ";
  s << c.jobs << " threads, " << std::fixed << std::setprecision(2) << c.seconds << " s\n";
  if (!r.no_layout.empty()) {
    s << "no layout: " << r.no_layout << "\n";
    return s.str();
  }
  s << "score = IN parameter length / boundary parameter length, ranked by the " << push_name(o) << " score\n";
  // What a score is, and is not (docs/design.md, "Reading a design").
  s << "  exact lower bounds at resolution " << to_string(o.resolution)
    << ": stretches left PARTIAL there count as not IN; the best of the listed candidates only\n"
    << "  parameter length: a polyline edge counts 1 and a B-spline its knot span, whatever their arc length\n"
    << "  sustained: J at the seat (every gap 0), IN = seats and stays under a sustained push in the model "
       "linearised at the seat; one-step: S with every gap "
    << to_string(o.gap) << (o.gap == 0 ? " (with gap 0 every seat is already reached: one-step 1 says nothing)" : "")
    << "\n";
  for (std::size_t k = 0; k < r.layouts.size(); ++k) {
    const DesignLayout& l = r.layouts[k];
    s << "#" << k + 1 << " fixels";
    for (int i : l.fixels) {
      const DesignCandidate& c = r.candidates.at(i);
      s << " [" << i << "] curve " << c.curve << " u=" << to_string(c.u);
    }
    s << "\n   sustained " << score_text(l.sustained_score)
      << (l.sustained_empty && *l.sustained_empty ? " (J empty)" : "") << ", one-step " << score_text(l.step_score)
      << std::setprecision(4) << ", J width " << l.j_width << " (of all wrench directions), conditioning "
      << significant(l.conditioning) << "\n";
    if (l.conditioning < kNearlySingular && l.curved_contacts > 0)
      s << "   warning: nearly singular (conditioning below " << significant(kNearlySingular) << ") with "
        << l.curved_contacts << " of its contacts on curved pieces: the three normal lines nearly meet in one "
        << "point, and the part's curvature there, which the linearised model omits, decides. Box2D at its "
           "default settings failed pushes on 51 of the 188 such layouts measured, a finer engine on 6, all below "
        << significant(kVeryNearlySingular) << (l.conditioning < kVeryNearlySingular ? " as this one is" : "")
        << " (docs/design.md): validate with `fixel region LAYOUT --push sustained --validate 10 --steps-per-h "
           "16000 --velocity-iterations 100 --position-iterations 50`\n";
    if (!l.step_seat.empty()) {
      // An exact refusal (polyline edges) proves there is no seat; a local
      // search's ("near the scene pose", curved pieces) does not.
      const bool searched = l.step_seat.find("near the scene pose") != std::string::npos;
      s << "   warning: with gap " << to_string(o.gap)
        << (searched ? " fixel's search found no seated pose near the scene pose (a local search on curved pieces, "
                       "not a proof: the part may still seat): "
                     : " no pose closes every gap, so the part cannot seat in this fixture and its one-step score "
                       "says nothing: ")
        << l.step_seat << "\n";
    }
    if (!l.note.empty()) s << "   note: " << l.note << "\n";
  }
  if (!r.layouts.empty() && r.layouts.front().score == 0)
    s << "every listed layout scores 0: none has an IN stretch at resolution " << to_string(o.resolution)
      << " (J or S empty, or the resolution too coarse), so their order is only the triples' order\n";
  if (shipped)
    s << "shipped layout: sustained " << score_text(shipped->sustained_score) << ", one-step "
      << score_text(shipped->step_score) << "\n"
      << (shipped->note.empty() ? "" : "   note: " + shipped->note + "\n");
  return s.str();
}

void write_design_svg(const std::string& path, const Scene& part, const DesignResult& r, const DesignOptions& o,
                      int panels) {
  if (!part.body.boundary) throw SceneError("body.boundary", "", "is missing: nothing to draw");
  const Boundary& b = *part.body.boundary;
  const int n = std::min<int>(panels, static_cast<int>(r.layouts.size()));
  // Display: the outline sampled in doubles.
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& piece : b.pieces)
    for (int j = 0; j <= 16; ++j) {
      const Vec2 p = piece.point(Rational(j, 16));
      x0 = std::min(x0, to_double(p.x));
      x1 = std::max(x1, to_double(p.x));
      y0 = std::min(y0, to_double(p.y));
      y1 = std::max(y1, to_double(p.y));
    }
  const double size = 320, margin = 40, extent = std::max(x1 - x0, y1 - y0) * 1.3;
  const double scale = size / extent;
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const int cols = std::max(n, 1);
  std::vector<std::vector<Rational>> piece_starts(b.curves.size());  // per curve, increasing
  for (const auto& piece : b.pieces) piece_starts.at(piece.curve).push_back(piece.u0);
  for (auto& starts : piece_starts) std::sort(starts.begin(), starts.end());
  std::ostringstream s;
  const double width = cols * (size + margin) + margin, height = size + 2 * margin + 30;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height << "' viewBox='0 0 "
    << width << " " << height << "' font-family='sans-serif' font-size='12'>\n";
  s << "<rect width='100%' height='100%' fill='white'/>\n";
  s << "<text x='" << margin << "' y='20'>" << part.name << ": best layouts by the " << push_name(o)
    << " score (green: IN, grey: OUT, orange: PARTIAL; red: fixels, each line on the side it touches from; "
       "circle: centre of mass)</text>\n";
  if (n == 0) s << "<text x='" << margin << "' y='60'>no layout: " << r.no_layout << "</text>\n";
  for (int k = 0; k < n; ++k) {
    const DesignLayout& l = r.layouts[k];
    const double ox = margin + k * (size + margin) + size / 2, oy = margin + 30 + size / 2;
    auto X = [&](double x) { return ox + (x - cx) * scale; };
    auto Y = [&](double y) { return oy - (y - cy) * scale; };
    const Region region = layout_region(part, r.candidates, l.fixels, o);
    for (const auto& iv : region.intervals) {
      const Curve& c = b.curves.at(iv.curve);
      const char* colour =
          iv.status == RegionStatus::kIn ? "#2a2" : (iv.status == RegionStatus::kOut ? "#999" : "#e90");
      s << "<polyline fill='none' stroke='" << colour << "' stroke-width='" << (iv.status == RegionStatus::kIn ? 4 : 2)
        << "' points='";
      // Samples between the piece ends inside the interval, so that a
      // corner is drawn as a corner (not cut by a chord).
      const std::vector<Rational>& starts = piece_starts.at(iv.curve);
      std::vector<Rational> ends{iv.u0};
      const auto first = std::upper_bound(starts.begin(), starts.end(), iv.u0);
      const auto last = std::lower_bound(starts.begin(), starts.end(), iv.u1);
      if (first < last) ends.insert(ends.end(), first, last);  // none for a corner's zero-length interval
      ends.push_back(iv.u1);
      const int m = ends.size() > 2 ? 4 : 12;
      for (std::size_t e = 0; e + 1 < ends.size(); ++e)
        for (int j = e == 0 ? 0 : 1; j <= m; ++j) {
          const Vec2 p = c.point(ends[e] + (ends[e + 1] - ends[e]) * Rational(j, m));
          s << X(to_double(p.x)) << "," << Y(to_double(p.y)) << " ";
        }
      s << "'/>\n";
    }
    for (int i : l.fixels) {
      const DesignCandidate& c = r.candidates.at(i);
      const double px = to_double(c.point.x), py = to_double(c.point.y);
      const double nx = to_double(c.normal.x), ny = to_double(c.normal.y), nn = std::hypot(nx, ny);
      const double L = extent * 0.08;
      s << "<line x1='" << X(px - L * nx / nn) << "' y1='" << Y(py - L * ny / nn) << "' x2='" << X(px) << "' y2='"
        << Y(py) << "' stroke='#c00' stroke-width='2'/>\n";
      s << "<circle cx='" << X(px) << "' cy='" << Y(py) << "' r='4' fill='#c00'/>\n";
    }
    const Vec2& com = part.body.p_AoCm_A;
    s << "<circle cx='" << X(to_double(com.x)) << "' cy='" << Y(to_double(com.y))
      << "' r='3' fill='none' stroke='black'/>\n";
    std::ostringstream caption;
    caption << "#" << k + 1 << " score " << std::fixed << std::setprecision(4) << to_double(l.score) << ", fixels "
            << l.fixels[0] << ", " << l.fixels[1] << ", " << l.fixels[2];
    s << "<text x='" << ox - size / 2 << "' y='" << oy + size / 2 + 20 << "'>" << caption.str() << "</text>\n";
  }
  s << "</svg>\n";
  internal::write_file(path, "svg(path)", [&](std::ostream& out) { out << s.str(); });
}

}  // namespace fixel
