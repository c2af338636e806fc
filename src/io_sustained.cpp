// Reports of the sustained-push set J: the JSON contract and readable text.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/approach_json.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/json_approx.h"
#include "fixel/internal/off_sidecar.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/io.h"
#include "fixel/off_io.h"
#include "fixel/progress.h"
#include "fixel/seat_report.h"
#include "fixel/seating.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

// |θ*| from which the seat report warns: past it, J's failures in Box2D
// grow (docs/physics.md, "J′ in the engine"). Not a guarantee below it.
constexpr double kValidatedRotation = 0.2;

}  // namespace

std::string seat_rotation_note(const SeatedPose& q) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(5);
  // The commands named here are whole ones: this note ends the reports of
  // seat --sustained, push-plan and region, which take neither option.
  const std::string validate =
      "validate in Box2D with `fixel region SCENE --push sustained --validate N` or `fixel push SCENE --at K:U`";
  if (std::abs(q.approx[2]) >= kValidatedRotation) {
    out << "warning: |theta*| = " << std::abs(q.approx[2]) << " rad >= " << kValidatedRotation
        << " rad: J is decided at q* only; in Box2D, pushes in J failed more often on the way to such seats "
           "(docs/physics.md). ";
    if (q.exact)
      out << "Use the approach-aware J' (`fixel region SCENE --push sustained --approach`), and " << validate << ".\n";
    else
      out << "J' needs an exact seat, which this scene's curved contact does not give: " << validate << ".\n";
  } else {
    out << "note: |theta*| = " << std::abs(q.approx[2])
        << " rad; J (and J') are decided in the model linearised at q*: far from the seat the part can still escape "
           "(docs/physics.md, \"Where J and J' fail\"); "
        << validate << ".\n";
  }
  return out.str();
}

namespace {

json exact3(const std::array<QuadraticIrrational, 3>& v) {
  return json::array({v[0].text(), v[1].text(), v[2].text()});
}

json approx3(const std::array<QuadraticIrrational, 3>& v) {
  return json::array({v[0].approx(), v[1].approx(), v[2].approx()});
}

json enclosure3(const std::array<std::array<double, 2>, 3>& e) {
  return json::array(
      {json::array({e[0][0], e[0][1]}), json::array({e[1][0], e[1][1]}), json::array({e[2][0], e[2][1]})});
}

json cone_json(const AlgebraicCone& c) {
  json rays = json::array(), rays_approx = json::array(), hs = json::array();
  if (!c.exact) {  // certified enclosures [lo, hi] instead of exact strings
    for (const auto& r : c.rays_enclosure) {
      rays.push_back(enclosure3(r));
      rays_approx.push_back(json::array({(r[0][0] + r[0][1]) / 2, (r[1][0] + r[1][1]) / 2, (r[2][0] + r[2][1]) / 2}));
    }
    for (const auto& a : c.closed_enclosure) hs.push_back({{"a", enclosure3(a)}, {"c", "0"}, {"strict", false}});
    for (const auto& a : c.strict_enclosure) hs.push_back({{"a", enclosure3(a)}, {"c", "0"}, {"strict", true}});
    return {{"rays", rays}, {"rays_approx", rays_approx}, {"halfspaces", hs}};
  }
  for (const auto& r : c.rays) {
    rays.push_back(exact3(r));
    rays_approx.push_back(approx3(r));
  }
  // A row with an entry in Q(√d) gets its doubles here (add_approx reads
  // rational strings only; a rational row gets them there, as before).
  auto row = [](const std::array<QuadraticIrrational, 3>& a, bool strict) {
    json h = {{"a", exact3(a)}};
    if (a[0].b != 0 || a[1].b != 0 || a[2].b != 0) h["a_approx"] = approx3(a);
    h["c"] = "0";
    h["strict"] = strict;
    return h;
  };
  for (const auto& a : c.closed) hs.push_back(row(a, false));
  for (const auto& a : c.strict) hs.push_back(row(a, true));
  return {{"rays", rays}, {"rays_approx", rays_approx}, {"halfspaces", hs}};
}

std::string fixed(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

std::string approach_text(const ApproachSet& A, const std::optional<ApproachVerdict>& v) {
  std::ostringstream out;
  out << "approach-aware J' (no pair of fixels holds the part at any two-contact pose with theta from 0 to "
         "theta*, docs/theory.md 10.7): ";
  if (!A.decided)
    out << "not decided: " << A.undecided_reason << "\n";
  else if (!A.on_edges)
    out << "EMPTY: " << A.edge_reason << "\n";
  else if (A.empty)
    out << "EMPTY (J is empty)\n";
  else
    out << "decided exactly for each wrench (--wrench); tan(theta*/2) = " << A.t_star.text() << "\n";
  if (v) {
    out << "  the wrench: ";
    if (!v->contains)
      out << "undecided: " << v->why_not << "\n";
    else
      out << (*v->contains ? "IN J' (no pair can hold the part on its way to the seat)" : "not in J': " + v->why_not)
          << "\n";
  }
  return out.str();
}

}  // namespace

nlohmann::ordered_json internal::approach_json(const ApproachSet& A, const std::optional<ApproachVerdict>& v) {
  using json = nlohmann::ordered_json;
  json out;
  out["decided"] = A.decided;
  if (!A.decided) out["undecided_reason"] = A.undecided_reason;
  out["t_star"] = A.decided ? json(A.t_star.text()) : json(nullptr);  // unknown, not 0, when undecided
  out["theta_star"] = A.theta_star;
  out["on_edges"] = A.decided ? json(A.on_edges) : json(nullptr);
  if (A.decided && !A.on_edges) out["edge_reason"] = A.edge_reason;
  out["empty"] = A.decided && A.empty ? json(true) : json(nullptr);
  if (v) {
    out["contains"] = v->contains ? json(*v->contains) : json(nullptr);
    if (!v->why_not.empty()) out["why_not"] = v->why_not;
    if (v->hold) {
      json h = {{"fixels", json::array({v->hold->fixels[0], v->hold->fixels[1]})}, {"theta", v->hold->theta}};
      h["t"] = v->hold->at_seat
                   ? json("t_star")
                   : json(v->hold->t->is_rational()
                              ? to_string(v->hold->t->lo)
                              : certified_decimal(refined(*v->hold->t, parse_rational("1e-13")), 12));  // 12 digits
      out["hold"] = h;
    }
  }
  return out;
}

namespace {

// J, and J′ through the J it refines, against the scene being written.
void check_sets_of(const Scene& scene, const SustainedSet& J, const ApproachSet* approach) {
  if (J.data) internal::check_built_from(*J.data, scene, "J");
  if (approach && approach->J.data) internal::check_built_from(*approach->J.data, scene, "J'");
}

}  // namespace

std::string sustained_json(const Scene& scene, const SustainedSet& J, const std::optional<WrenchVerdict>& wrench,
                           const ApproachSet* approach, const std::optional<ApproachVerdict>& approach_wrench,
                           bool with_seating) {
  check_sets_of(scene, J, approach);
  json doc = json::object();
  if (with_seating) {
    try {
      const SeatingSet S = seating_set(scene);
      doc = json::parse(seat_json(scene, S, seat_report(scene, S, std::nullopt, nullptr, false)));
    } catch (const StoppedError&) {
      throw;  // the run's stop, not S's absence
    } catch (const Error& e) {
      doc["scene"] = scene.name;
      doc["seating_unavailable"] = e.what();
    }
  }
  doc["scene"] = scene.name;
  doc["seated_pose"] = json::parse(seated_pose_json(J.pose));
  json sustained;
  sustained["exact"] = J.cone.exact;
  sustained["cone"] = cone_json(J.cone);
  json jams = json::array();
  for (const auto& jam : J.jam_cones) {
    json j = cone_json(jam.cone);
    j["fixels"] = json::array({jam.fixels[0], jam.fixels[1]});
    jams.push_back(j);
  }
  sustained["jam_cones"] = jams;
  json pieces = json::array();
  for (const auto& p : J.pieces) pieces.push_back(cone_json(p));
  sustained["pieces"] = J.pieces_decided ? pieces : json(nullptr);
  sustained["empty"] = J.pieces_decided ? json(J.empty) : json(nullptr);
  if (J.empty) sustained["empty_reason"] = J.empty_reason;
  sustained["strongly_stable"] = J.strongly_stable;
  sustained["stability_checks"] = J.stability_checks;
  json mu = json::array();
  for (const auto& m : J.mu) mu.push_back(to_string(m));
  sustained["mu"] = mu;
  doc["sustained"] = sustained;
  if (wrench) {
    json w = json::array();
    for (int k = 0; k < wrench->wrench.size(); ++k) w.push_back(to_string(wrench->wrench[k]));
    doc["wrench"] = w;
    doc["contains"] = wrench->contains ? json(*wrench->contains) : json(nullptr);
    if (!wrench->why_not.empty()) doc["why_not"] = wrench->why_not;
  }
  if (approach) doc["approach"] = internal::approach_json(*approach, approach_wrench);
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

std::string seated_pose_json(const SeatedPose& q) {
  json pose;
  const bool rational_zero_rotation = q.exact && (*q.exact)[0].b == 0 && (*q.exact)[1].b == 0 && (*q.exact)[2].b == 0 &&
                                      (*q.exact)[3].b == 0 && (*q.exact)[3].a == 0 && (*q.exact)[2].a == 1;
  pose["exact"] = rational_zero_rotation ? json::array({to_string((*q.exact)[0].a), to_string((*q.exact)[1].a), "0"})
                                         : json(nullptr);
  pose["approx"] = json::array({q.approx[0], q.approx[1], q.approx[2]});
  if (q.exact)
    pose["algebraic"] = {{"x", (*q.exact)[0].text()},
                         {"y", (*q.exact)[1].text()},
                         {"cos", (*q.exact)[2].text()},
                         {"sin", (*q.exact)[3].text()}};
  pose["enclosure"] = json::array();
  for (const auto& e : q.enclosure) pose["enclosure"].push_back(json::array({e[0], e[1]}));
  pose["theta_abs"] = std::abs(q.approx[2]);
  pose["at_scene_pose"] = q.at_scene_pose;
  json contacts = json::array();
  for (std::size_t i = 0; i < q.contact_curve.size(); ++i) {
    json c = {{"fixel", i}, {"curve", q.contact_curve[i]}, {"u_approx", q.contact_u[i]}};
    if (i < q.p_BoG_B.size()) {
      c["point_B"] = json::array({q.p_BoG_B[i][0].text(), q.p_BoG_B[i][1].text()});
      c["normal_B"] = json::array({to_string(q.n_B[i].x), to_string(q.n_B[i].y)});
    } else {
      const auto& g = q.p_BoG_B_enclosure[i];
      const auto& t = q.tangent_B_enclosure[i];
      c["point_B_enclosure"] = json::array({json::array({g[0][0], g[0][1]}), json::array({g[1][0], g[1][1]})});
      c["tangent_B_enclosure"] = json::array({json::array({t[0][0], t[0][1]}), json::array({t[1][0], t[1][1]})});
    }
    contacts.push_back(c);
  }
  pose["contacts"] = contacts;
  if (!q.exact)
    pose["cos_sin_enclosure"] = json::array({json::array({q.cos_sin_enclosure[0][0], q.cos_sin_enclosure[0][1]}),
                                             json::array({q.cos_sin_enclosure[1][0], q.cos_sin_enclosure[1][1]})});
  return pose.dump();
}

std::string sustained_text(const Scene& scene, const SustainedSet& J, const std::optional<WrenchVerdict>& wrench,
                           const ApproachSet* approach, const std::optional<ApproachVerdict>& approach_wrench) {
  check_sets_of(scene, J, approach);
  std::ostringstream out;
  const SeatedPose& q = J.pose;
  out << "Sustained push on scene \"" << scene.name << "\": the wrench set J at the seated pose q*\n";
  out << "seated pose q*: x ~ " << fixed(q.approx[0]) << " m, y ~ " << fixed(q.approx[1]) << " m, theta ~ "
      << fixed(q.approx[2]) << " rad (|theta*| = " << fixed(std::abs(q.approx[2])) << " rad)"
      << (q.at_scene_pose ? ", the scene pose (every gap is 0)"
                          : (q.exact ? ", exact in a quadratic field" : ", enclosed (curved contacts)"))
      << "\n";
  if (!q.exact) {
    // Enough digits that the two ends differ (the stream's fixed 5 showed
    // [-0.30031, -0.30031]): the enclosure's width is the point.
    std::ostringstream ends;
    ends << std::setprecision(17) << "[" << q.enclosure[2][0] << ", " << q.enclosure[2][1] << "]";
    out << "  certified enclosure (contacts on curved pieces): theta in " << ends.str()
        << " rad; tests it cannot decide are reported as undecided/partial\n";
  }
  if (q.exact && !q.at_scene_pose)
    out << "  exact: x = " << (*q.exact)[0].text() << ", y = " << (*q.exact)[1].text()
        << ",\n         cos theta = " << (*q.exact)[2].text() << ", sin theta = " << (*q.exact)[3].text() << "\n";
  out << seat_rotation_note(q);
  out << "friction used (upper ends):";
  for (const auto& m : J.mu) out << " " << to_string(m);
  out << "\n";
  if (!J.pieces_decided) {
    out << "J: its pieces could not be decided at the enclosure's width (membership tests still are, or say "
           "undecided)\n";
  } else if (J.empty) {
    out << "J is EMPTY: no single sustained push can be trusted to seat this part: " << J.empty_reason << ".\n";
  } else {
    out << "J: " << J.pieces.size() << " convex cone piece(s); any push magnitude works (J is a cone).\n";
    out << "strongly stable at the seat for every w in J: " << (J.strongly_stable ? "yes" : "no")
        << " (theorem, docs/theory.md 10.3; contact-mode enumeration checked " << J.stability_checks << " wrench(es)"
        << (J.stability_checks == 0 ? ": it runs only at a rational seat, and this one is not" : "") << ")\n";
  }
  out << "cone {w : -w in int cone(W_n*)}: rays (fx, fy, m) ~";
  for (const auto& r : J.cone.rays)
    out << " (" << fixed(r[0].approx(), 4) << ", " << fixed(r[1].approx(), 4) << ", " << fixed(r[2].approx(), 4) << ")";
  for (const auto& r : J.cone.rays_enclosure)
    out << " (" << fixed((r[0][0] + r[0][1]) / 2, 4) << ", " << fixed((r[1][0] + r[1][1]) / 2, 4) << ", "
        << fixed((r[2][0] + r[2][1]) / 2, 4) << ")";
  out << "\n";
  if (wrench) {
    const VectorQ& w = wrench->wrench;
    out << "wrench (" << to_string(w[0]) << ", " << to_string(w[1]) << ", " << to_string(w[2]) << ") N, N*m: ";
    if (!wrench->contains)
      out << "undecided: " << wrench->why_not << "\n";
    else
      out << (*wrench->contains ? "IN J (sustained push: seats and stays)" : "not in J: " + wrench->why_not) << "\n";
  }
  if (approach) out << approach_text(*approach, approach_wrench);
  return out.str();
}

}  // namespace fixel

namespace fixel {

namespace {

// A row's double for the picture; past double range there is no picture
// (a Rational of an infinite double would abort in GMP).
Rational drawable(double x) {
  if (!std::isfinite(x))
    throw InputError("J", std::to_string(x),
                     "a row of J is beyond double range: the scene's numbers are too large to draw (J itself is "
                     "exact: sustained_json gives it)");
  return Rational(x);
}

// A display-only rational row: the double nearest each coordinate, read
// back exactly (OFF vertices are doubles anyway).
Halfspace display_row(const std::array<QuadraticIrrational, 3>& a) {
  VectorQ v(3);
  for (int k = 0; k < 3; ++k) v[k] = drawable(a[k].approx());
  return {v, Rational(0)};
}

// The same for a row known only by certified enclosures (q* enclosed):
// each entry's midpoint.
Halfspace display_row(const std::array<std::array<double, 2>, 3>& a) {
  VectorQ v(3);
  for (int k = 0; k < 3; ++k) v[k] = drawable((a[k][0] + a[k][1]) / 2);
  return {v, Rational(0)};
}

std::vector<std::string> write_cone_off(const std::string& dir, const std::string& name, const AlgebraicCone& cone,
                                        json meta) {
  // Without exact rows (q* only enclosed) the enclosures' midpoints: the
  // box alone would be drawn as the cone.
  std::vector<Halfspace> rows;
  if (cone.exact) {
    for (const auto& a : cone.closed) rows.push_back(display_row(a));
    for (const auto& a : cone.strict) rows.push_back(display_row(a));
  } else {
    for (const auto& a : cone.closed_enclosure) rows.push_back(display_row(a));
    for (const auto& a : cone.strict_enclosure) rows.push_back(display_row(a));
  }
  Box box;
  box.lo = VectorQ::Constant(3, Rational(-1));
  box.hi = VectorQ::Constant(3, Rational(1));
  for (const auto& h : box.halfspaces()) rows.push_back(h);
  const std::string path = (std::filesystem::path(dir) / name).string();
  meta["box"] = {{"lo", {"-1", "-1", "-1"}}, {"hi", {"1", "1", "1"}}};
  meta["coordinates"] =
      cone.exact ? "rows rounded to double before clipping, vertices rounded to double: a picture (exact: seat "
                   "--sustained --json)"
                 : "q* is only enclosed: rows are the midpoints of their certified enclosures, vertices rounded to "
                   "double: a picture (the enclosures: seat --sustained --json)";
  return internal::write_off_with_sidecar(path, rows, 3, meta, "dump_sustained_off(directory)");
}

}  // namespace

std::vector<std::string> dump_sustained_off(const Scene& scene, const SustainedSet& J, const std::string& dir) {
  check_sets_of(scene, J, nullptr);
  internal::make_output_folder(dir, "dump_sustained_off(directory)");
  auto meta = [&](const std::string& what, const std::string& description) {
    return json{{"what", what},
                {"description", description},
                {"scene", scene.name},
                {"space", "wrench (fx, fy, m), world frame at the seated pose"}};
  };
  std::vector<std::string> written;
  auto add = [&](const std::vector<std::string>& paths) { written.insert(written.end(), paths.begin(), paths.end()); };
  add(write_cone_off(dir, "sustained_cone.off", J.cone,
                     meta("sustained_cone", "the cone {w : -w in int cone(W_n*)} of the sustained-push set J")));
  for (const auto& jam : J.jam_cones) {
    json m = meta("sustained_jam",
                  "jam cone -(FC_" + std::to_string(jam.fixels[0]) + " + FC_" + std::to_string(jam.fixels[1]) + ")");
    m["fixels"] = {jam.fixels[0], jam.fixels[1]};
    add(write_cone_off(dir,
                       "sustained_jam_" + std::to_string(jam.fixels[0]) + "_" + std::to_string(jam.fixels[1]) + ".off",
                       jam.cone, m));
  }
  for (std::size_t k = 0; k < J.pieces.size(); ++k) {
    json m = meta("sustained_piece", "convex piece " + std::to_string(k) + " of J (its closure)");
    m["piece"] = k;
    add(write_cone_off(dir, "sustained_piece_" + std::to_string(k) + ".off", J.pieces[k], m));
  }
  return written;
}

}  // namespace fixel
