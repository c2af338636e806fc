// Reports of the physics check: JSON, text and the trajectory SVG.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/readable.h"
#include "fixel/physics.h"

namespace fixel::physics {

using fixel::to_string;  // physics::to_string(Outcome) would hide it

namespace {

using json = nlohmann::ordered_json;  // keys in the order written, as the region document has them

json pose_json(const Pose& p) { return json::array({p.x, p.y, p.theta}); }

json counts_json(const Validation& v) {
  return {{"pushes", v.pushes},
          {"seated", v.seated},
          {"jammed", v.jammed},
          {"escaped", v.escaped},
          {"timeout", v.timeout},
          {"warned", v.warned},
          {"seated_warned", v.seated_warned}};
}

std::string counts_text(const Validation& v) {
  return std::to_string(v.seated) + " of " + std::to_string(v.pushes) + " pushes seated (" + std::to_string(v.jammed) +
         " jammed, " + std::to_string(v.escaped) + " escaped, " + std::to_string(v.timeout) + " timeout)";
}

std::string list(const std::vector<int>& v) {
  std::string s;
  for (int i : v) s += (s.empty() ? "" : ", ") + std::to_string(i);
  return s.empty() ? "none" : s;
}

}  // namespace

std::string push_json(const Scene& scene, const Wrench& w, const PushResult& r) {
  json doc;
  doc["scene"] = scene.name;
  doc["engine"] = "Box2D 2.4";
  doc["outcome"] = to_string(r.outcome);
  doc["time_to_seat"] = r.time_to_seat ? json(*r.time_to_seat) : json(nullptr);
  doc["final_pose"] = pose_json(r.final_pose);
  doc["final_gaps"] = r.final_gaps;
  doc["contacts_at_rest"] = r.contacts_at_rest;
  doc["open_fixels"] = r.open_fixels;
  doc["wrench"] = json::array({w.fx, w.fy, w.m});
  doc["time"] = r.time_end;
  doc["steps"] = r.steps;
  doc["dt"] = r.dt;
  doc["steps_per_h"] = r.steps_per_h;
  doc["velocity_iterations"] = r.velocity_iterations;
  doc["position_iterations"] = r.position_iterations;
  doc["length_scale"] = r.length_scale;
  doc["part_size"] = r.part_size;
  doc["gap_tolerance"] = r.gap_tolerance;
  doc["rest_speed"] = r.rest_speed;
  doc["time_scale"] = r.time_scale;
  doc["warnings"] = r.warnings;
  json events = json::array();
  for (const auto& e : r.events) events.push_back({{"t", e.t}, {"fixel", e.fixel}, {"begin", e.begin}});
  doc["events"] = events;
  return doc.dump(2) + "\n";
}

std::string push_text(const Scene& scene, const Wrench& w, const PushResult& r) {
  std::ostringstream out;
  out << std::setprecision(6);
  out << "Push on scene \"" << scene.name << "\" in Box2D 2.4: wrench (" << w.fx << ", " << w.fy << ", " << w.m
      << ")\n";
  out << "outcome: " << to_string(r.outcome);
  if (r.time_to_seat) out << " at t = " << *r.time_to_seat << " s";
  if (r.outcome == Outcome::kJammed) out << " (open: fixel " << list(r.open_fixels) << ")";
  out << "\n";
  out << "final pose (x m, y m, theta rad): (" << r.final_pose.x << ", " << r.final_pose.y << ", " << r.final_pose.theta
      << ") after " << r.time_end << " s\n";
  out << "final gaps (m):";
  for (double g : r.final_gaps) out << " " << g;
  out << "  (seated below " << r.gap_tolerance << " m)\n";
  out << "contacts at the end: " << list(r.contacts_at_rest) << "\n";
  out << "engine: dt " << r.dt << " s (h/" << r.steps_per_h << "), " << r.velocity_iterations << " velocity and "
      << r.position_iterations << " position iterations, " << r.steps << " steps, length scale " << r.length_scale
      << " units/m, part size " << r.part_size << " m; the push's time scale " << r.time_scale << " s\n";
  out << "a measurement in the engine (floats), not an exact decision: seated = every gap below " << r.gap_tolerance
      << " m while slower than " << r.rest_speed << " m/s for one h (docs/physics.md, \"Outcomes\")\n";
  for (const auto& warning : r.warnings) out << "warning: " << warning << "\n";
  return out.str();
}

namespace {

// The push on the picture: an arrow along its force's line of action at the
// start, ending where that line enters the part (a finger's contact), or at
// the line's point nearest the centre of mass when it misses the outline.
// None for a zero force (a pure moment, said in the caption); the caller
// also leaves out a line far off the part.
std::optional<std::array<std::array<double, 2>, 2>> push_arrow(const Wrench& w, double cx, double cy,
                                                               const std::vector<std::array<double, 2>>& outline,
                                                               double length) {
  const double f = std::hypot(w.fx, w.fy);
  if (!(f > 0) || !std::isfinite(f)) return std::nullopt;
  const double ux = w.fx / f, uy = w.fy / f;
  // r0 = m (Fy, −Fx)/|F|²: r0 × F = m, the point of the line nearest c.
  const double px = cx + w.m * w.fy / (f * f), py = cy - w.m * w.fx / (f * f);
  double entry = INFINITY;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % outline.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1], denom = ux * ey - uy * ex;
    if (denom == 0) continue;
    const double ax = a[0] - px, ay = a[1] - py;
    const double t = (ax * ey - ay * ex) / denom, s = (ax * uy - ay * ux) / denom;
    if (s >= 0 && s <= 1) entry = std::min(entry, t);
  }
  const double tip_x = std::isfinite(entry) ? px + entry * ux : px, tip_y = std::isfinite(entry) ? py + entry * uy : py;
  return std::array<std::array<double, 2>, 2>{{{tip_x - length * ux, tip_y - length * uy}, {tip_x, tip_y}}};
}

}  // namespace

void write_push_svg(const std::string& path, const Scene& scene, const PushResult& r, const Wrench* w) {
  const PartPolygon poly = part_polygon(scene);
  const double cx = to_double(scene.body.p_AoCm_A.x), cy = to_double(scene.body.p_AoCm_A.y);
  auto place = [&](const Pose& p, const std::array<double, 2>& v) {
    const double c = std::cos(p.theta), s = std::sin(p.theta), dx = v[0] - cx, dy = v[1] - cy;
    return std::array<double, 2>{cx + p.x + c * dx - s * dy, cy + p.y + s * dx + c * dy};
  };
  std::vector<std::array<double, 2>> fixels;
  for (const auto& f : scene.fixels)
    fixels.push_back({to_double(f.p_AoF_A.x - f.gap * f.n_A.x), to_double(f.p_AoF_A.y - f.gap * f.n_A.y)});
  // Fit everything drawn into the picture.
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  auto grow = [&](const std::array<double, 2>& q) {
    x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  };
  for (const auto& s : r.trajectory)
    for (const auto& v : poly.outline) grow(place(s.pose, v));
  for (const auto& f : fixels) grow(f);
  std::optional<std::array<std::array<double, 2>, 2>> arrow;
  // A line of action far from the part (a near-pure moment) is not drawn:
  // fitting it in would shrink the part to a dot. The caption gives it.
  double line_distance = 0;
  bool off_picture = false;
  if (w) {
    const double extent = std::max({x1 - x0, y1 - y0, 1e-12});
    arrow = push_arrow(*w, cx, cy, poly.outline, 0.2 * extent);
    line_distance = std::abs(w->m) / std::hypot(w->fx, w->fy);
    if (arrow && !(line_distance <= 2 * extent)) {
      arrow.reset();
      off_picture = true;
    }
    if (arrow)
      for (const auto& q : *arrow) grow(q);
  }
  const double W = 640, margin = 20, span = std::max({x1 - x0, y1 - y0, 1e-12});
  const double k = (W - 2 * margin) / span, H = (y1 - y0) * k + 2 * margin + (w ? 92 : 76);  // + the caption lines
  auto X = [&](double x) { return margin + (x - x0) * k; };
  auto Y = [&](double y) { return margin + (y1 - y) * k; };
  auto outline = [&](const Pose& p, const std::string& style) {
    std::ostringstream o;
    o << "<polygon style=\"" << style << "\" points=\"";
    for (const auto& v : poly.outline) {
      const auto q = place(p, v);
      o << X(q[0]) << "," << Y(q[1]) << " ";
    }
    o << "\"/>\n";
    return o.str();
  };
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
      << " " << H << "\" font-family=\"sans-serif\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << outline(Pose{}, "fill:#dde8f5;stroke:#6a8fbf;stroke-width:1");
  const std::size_t every = std::max<std::size_t>(1, r.trajectory.size() / 25);
  for (std::size_t i = every; i + 1 < r.trajectory.size(); i += every)
    out << outline(r.trajectory[i].pose, "fill:none;stroke:#999;stroke-width:0.5;stroke-opacity:0.6");
  out << outline(r.final_pose, std::string("fill:none;stroke:") +
                                   (r.outcome == Outcome::kSeated ? "#1a7f37" : "#c62828") + ";stroke-width:1.5");
  out << "<polyline style=\"fill:none;stroke:#333;stroke-dasharray:3,2\" points=\"";
  for (const auto& s : r.trajectory) out << X(cx + s.pose.x) << "," << Y(cy + s.pose.y) << " ";
  out << "\"/>\n";
  // Touches as rings of radius 7, leaves of radius 10: both stay visible at one fixel.
  for (const auto& e : r.events) {
    const auto& f = fixels[e.fixel];
    out << "<circle cx=\"" << X(f[0]) << "\" cy=\"" << Y(f[1]) << "\" r=\"" << (e.begin ? 7 : 10)
        << "\" style=\"fill:none;stroke:" << (e.begin ? "#e69500" : "#8e24aa")
        << ";stroke-opacity:0.6\"><title>t=" << e.t << " fixel " << e.fixel << (e.begin ? " touches" : " leaves")
        << "</title></circle>\n";
  }
  for (std::size_t i = 0; i < fixels.size(); ++i)
    out << "<circle cx=\"" << X(fixels[i][0]) << "\" cy=\"" << Y(fixels[i][1]) << "\" r=\"3\" fill=\"black\"/>"
        << "<text x=\"" << X(fixels[i][0]) + 5 << "\" y=\"" << Y(fixels[i][1]) - 5 << "\" font-size=\"11\">" << i
        << "</text>\n";
  if (arrow) {
    const auto& [tail, tip] = *arrow;
    const double dx = X(tip[0]) - X(tail[0]), dy = Y(tip[1]) - Y(tail[1]), n = std::hypot(dx, dy);
    const double ux = dx / n, uy = dy / n, head = 9;
    out << "<g style=\"stroke:#d81b60;fill:#d81b60\"><title>the push: wrench (" << w->fx << ", " << w->fy << ", "
        << w->m << ") in the world frame, along its force's line of action</title><line x1=\"" << X(tail[0])
        << "\" y1=\"" << Y(tail[1]) << "\" x2=\"" << X(tip[0]) << "\" y2=\"" << Y(tip[1])
        << "\" stroke-width=\"2\"/><polygon points=\"" << X(tip[0]) << "," << Y(tip[1]) << " "
        << X(tip[0]) - head * ux - 0.5 * head * uy << "," << Y(tip[1]) - head * uy + 0.5 * head * ux << " "
        << X(tip[0]) - head * ux + 0.5 * head * uy << "," << Y(tip[1]) - head * uy - 0.5 * head * ux << "\"/></g>\n";
  }
  auto caption = [&](double y) {
    return "<text x=\"" + std::to_string(margin) + "\" y=\"" + std::to_string(y) + "\" font-size=\"12\">";
  };
  const double first = w ? H - 66 : H - 50;
  out << caption(first) << scene.name << ": " << to_string(r.outcome);
  if (r.time_to_seat) out << " at t = " << *r.time_to_seat << " s (at rest from then on)";
  out << "; run stopped at " << r.time_end << " s</text>\n";
  out << caption(first + 16) << r.events.size()
      << " contact events at the fixels (black): orange ring: touch, purple ring: leave</text>\n";
  out << caption(first + 32) << "blue: the part at the start; " << (r.outcome == Outcome::kSeated ? "green" : "red")
      << ": at the end; grey: every few steps; dashed: the centre of mass's path</text>\n";
  if (w) {
    if (arrow)
      out << caption(first + 48) << "magenta: the push (" << w->fx << ", " << w->fy << ", " << w->m
          << "), along its force's line of action";
    else if (off_picture)
      out << caption(first + 48) << "the push (" << w->fx << ", " << w->fy << ", " << w->m
          << "): its line of action passes " << line_distance << " m from the centre of mass, off the picture";
    else
      out << caption(first + 48) << "the push (" << w->fx << ", " << w->fy << ", " << w->m << ") is "
          << (w->m == 0 ? "zero" : "a pure moment");
    out << "</text>\n";
  }
  out << "</svg>\n";
  internal::write_file(path, "svg(path)", [&](std::ostream& file) { file << out.str(); });
}

std::string add_validation_json(const std::string& region_json_text, const RegionValidation& v) {
  json doc = json::parse(region_json_text);
  auto& intervals = doc["intervals"];
  for (std::size_t i = 0; i < v.intervals.size() && i < intervals.size(); ++i)
    if (v.intervals[i]) intervals[i]["validation"] = counts_json(*v.intervals[i]);
  json total = counts_json(v.total);
  total["seed"] = v.seed;
  total["model"] = v.model;
  total["time"] = to_string(v.options.time);
  total["steps_per_h"] = v.options.steps_per_h;
  total["velocity_iterations"] = v.options.velocity_iterations;
  total["position_iterations"] = v.options.position_iterations;
  total["engine"] = "Box2D 2.4";
  if (!v.first_warning.empty()) total["first_warning"] = v.first_warning;
  doc["validation"] = total;
  return doc.dump(2) + "\n";
}

std::string validation_text(const Region& region, const RegionValidation& v) {
  std::ostringstream out;
  for (std::size_t i = 0; i < v.intervals.size() && i < region.intervals.size(); ++i)
    if (v.intervals[i])
      out << "  validated curve " << region.intervals[i].curve << " u in ["
          << internal::readable(region.intervals[i].u0) << ", " << internal::readable(region.intervals[i].u1)
          << "]: " << counts_text(*v.intervals[i]) << "\n";
  out << "validation (Box2D 2.4, " << v.model << ", T = " << to_string(v.options.time) << " h, seed " << v.seed
      << "; dt = h/" << v.options.steps_per_h << ", " << v.options.velocity_iterations << "+"
      << v.options.position_iterations << " solver iterations): " << counts_text(v.total) << "\n";
  if (v.total.warned > 0)
    out << "warning: " << v.total.warned << " of " << v.total.pushes << " pushes: " << v.first_warning << "\n";
  return out.str();
}

}  // namespace fixel::physics
