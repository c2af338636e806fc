#include "fixel/io.h"
#include "fixel/internal/json_approx.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/json_exact.h"
#include "fixel/internal/readable.h"
#include "fixel/internal/seating_sets_check.h"
#include "fixel/off_io.h"
#include "fixel/wrench_cone.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

using internal::exact_json;

// Exact with decimals beside (docs/cli.md, "Numbers").
std::string text(const VectorQ& v) { return internal::readable(v); }

// The warning that other one-step outcomes exist.
std::string outcomes_warning(const OutcomeCount& c) {
  if (c.total <= 1) return "";
  return "  warning: the one-step model has " + std::to_string(c.total) + " outcomes for this impulse (" +
         std::to_string(c.seating) + " seat, " + std::to_string(c.total - c.seating) +
         " do not); `fixel solutions` lists them, `fixel seat --guaranteed` says whether every one seats.\n";
}

std::string halfspace_text(const Halfspace& h) {
  static const char* names[] = {"px", "py", "ptheta"};
  std::string s;
  for (int k = 0; k < h.a.size(); ++k) {
    if (h.a[k] == 0) continue;
    const Rational c = h.a[k];
    std::string coef = (c == 1 || c == -1) ? "" : to_string(boost::multiprecision::abs(c)) + "*";
    s += s.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    s += coef + names[k];
  }
  const std::string c = to_string(h.c);
  const std::string r = internal::readable(h.c);
  return s + " >= " + (r == c ? c : r);
}

}  // namespace

namespace {
json halfspaces_json(const std::vector<Halfspace>& hs) {
  json out = json::array();
  for (const auto& h : hs) out.push_back({{"a", exact_json(h.a)}, {"c", to_string(h.c)}});
  return out;
}
std::string polyhedron_text(const Polyhedron& P) {
  if (P.is_trivially_empty()) return "      (empty: a row 0 >= c with c > 0)\n";
  std::string s;
  for (const auto& h : P.closed) s += "      " + halfspace_text(h) + "\n";
  for (const auto& h : P.strict) {
    std::string t = halfspace_text(h);
    t.replace(t.find(">="), 2, "> ");
    s += "      " + t + "\n";
  }
  return s;
}
// " (all of dimension 3)" or " (7 of dimension 3; 2 lower-dimensional, with no volume: piece 4 of dimension 2,
// piece 8 of dimension 1)".
std::string pieces_dimension_text(const GuaranteedSet& G) {
  if (G.pieces.empty() || G.dimensions.size() != G.pieces.size()) return "";
  const int dof = G.pieces[0].dim;
  std::string low;
  int full = 0, lower = 0;
  for (std::size_t k = 0; k < G.dimensions.size(); ++k) {
    if (G.dimensions[k] == dof) {
      ++full;
      continue;
    }
    ++lower;
    low += (low.empty() ? "" : ", ") + std::string("piece ") + std::to_string(k) + " of dimension " +
           std::to_string(G.dimensions[k]);
  }
  if (lower == 0) return " (all of dimension " + std::to_string(dof) + ")";
  return " (" + std::to_string(full) + " of dimension " + std::to_string(dof) + "; " + std::to_string(lower) +
         " lower-dimensional, with no volume, kept so that the pieces partition G exactly: " + low + ")";
}
std::string modes_text(const std::vector<ContactMode>& modes) {
  std::string s;
  for (auto m : modes) s += (s.empty() ? "" : " ") + to_string(m);
  return s;
}
json seat_extras_json(const SeatReport& report, const GuaranteedSet* G) {
  json doc = json::object();
  if (G) {
    json g;
    g["non_seating"] = json::array();
    for (const auto& n : G->non_seating) {
      json modes = json::array();
      for (auto m : n.modes) modes.push_back(to_string(m));
      g["non_seating"].push_back({{"modes", modes},
                                  {"open_fixel", n.open_fixel},
                                  {"closed", halfspaces_json(n.impulses.closed)},
                                  {"strict", halfspaces_json(n.impulses.strict)}});
    }
    g["pieces"] = json::array();
    for (std::size_t k = 0; k < G->pieces.size(); ++k)
      g["pieces"].push_back({{"dimension", k < G->dimensions.size() ? json(G->dimensions[k]) : json(nullptr)},
                             {"closed", halfspaces_json(G->pieces[k].closed)},
                             {"strict", halfspaces_json(G->pieces[k].strict)}});
    g["lost_fraction"] = to_string(*report.lost_fraction);
    doc["guaranteed_set"] = g;
    if (report.impulse) doc["guaranteed"] = *report.impulse->guaranteed;
  }
  if (report.stable) {
    doc["stability_cone"] = halfspaces_json(report.stability_cone);
    doc["seat_and_stay"] = {{"halfspaces", halfspaces_json(report.seat_and_stay.closed)}};
    if (report.impulse) doc["seat_and_stay_contains"] = *report.impulse->seat_and_stay;
  }
  return doc;
}

std::string seat_extras_text(const SeatReport& report, const GuaranteedSet* G) {
  std::ostringstream out;
  if (G) {
    out << "Guaranteed set G (one-step: guaranteed, every outcome of the one-step model seats): " << G->pieces.size()
        << " convex piece(s)" << pieces_dimension_text(*G) << "; " << G->non_seating.size()
        << " non-seating set(s) meet S\n";
    for (const auto& n : G->non_seating)
      out << "  non-seating: modes " << modes_text(n.modes) << ", fixel " << n.open_fixel << " stays open, where\n"
          << polyhedron_text(n.impulses);
    out << "  lost fraction of S (grid sample, docs/theory.md §9): " << to_string(*report.lost_fraction) << "\n";
    if (report.impulse)
      out << "Impulse p = " << text(report.impulse->impulse)
          << (*report.impulse->guaranteed
                  ? " is IN G (one-step: guaranteed): every one-step outcome seats.\n"
                  : " is NOT in G: not every one-step outcome seats (one-step: not guaranteed).\n");
  }
  if (report.stable) {
    out << "Seat-and-stay set S ∩ h·C_stab (one-step: can seat, and the same wrench, sustained, is weakly stable at "
           "the seat):\n"
        << polyhedron_text(report.seat_and_stay);
    if (report.impulse)
      out << "Impulse p = " << text(report.impulse->impulse)
          << (*report.impulse->seat_and_stay
                  ? " is in the seat-and-stay set: some one-step outcome seats, and the same wrench held would keep "
                    "the seat weakly stable. This is not a guarantee: other outcomes and later steps may reopen a gap "
                    "(see --guaranteed, `fixel solutions`, and `seat --sustained`).\n"
                  : " is not in the seat-and-stay set.\n");
  }
  return out.str();
}

}  // namespace

std::string seat_json(const Scene& scene, const SeatingSet& S, const SeatReport& report, const GuaranteedSet* G) {
  internal::check_seating_sets_of(scene, S, G);
  json doc;
  doc["scene"] = scene.name;
  doc["dof"] = S.dof;
  doc["sliding"] = S.sliding;
  doc["velocity_after"] = exact_json(S.nu_plus);
  doc["tangential_velocity"] = exact_json(S.tangential_velocity);
  doc["apex"] = exact_json(S.apex);
  doc["rays"] = json::array();
  for (const auto& r : S.rays) doc["rays"].push_back(exact_json(r));
  doc["halfspaces"] = json::array();
  for (const auto& h : S.halfspaces) doc["halfspaces"].push_back({{"a", exact_json(h.a)}, {"c", to_string(h.c)}});
  if (report.impulse) {
    doc["impulse"] = exact_json(report.impulse->impulse);
    doc["contains"] = report.impulse->in_S;
    doc["meaning"] = "one-step: can seat";
    doc["outcomes"] = {{"total", report.impulse->outcomes.total}, {"seating", report.impulse->outcomes.seating}};
    if (report.impulse->y) {
      doc["y"] = exact_json(*report.impulse->y);
      doc["y_names"] = report.impulse->y_names;
    }
  }
  const json extras = seat_extras_json(report, G);  // items() must not outlive it
  for (const auto& [key, value] : extras.items()) doc[key] = value;
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

static std::string seat_basic_text(const Scene& scene, const SeatingSet& S, const SeatReport& report);

std::string seat_text(const Scene& scene, const SeatingSet& S, const SeatReport& report, const GuaranteedSet* G) {
  internal::check_seating_sets_of(scene, S, G);
  return seat_basic_text(scene, S, report) + seat_extras_text(report, G);
}

static std::string seat_basic_text(const Scene& scene, const SeatingSet& S, const SeatReport& report) {
  std::ostringstream out;
  out << "Seating set S of scene \"" << scene.name << "\" (dof " << S.dof << ", " << scene.num_contacts()
      << " fixels; the one-step model: one impulse, one backward-Euler step of h = "
      << internal::readable(scene.time_step) << " s)\n";
  out << (S.dof == 3 ? "  units: impulses in N*s (px, py) and N*m*s (ptheta); velocities in m/s and rad/s; frame A\n"
                     : "  units: impulses in N*s (px, py); velocities in m/s; frame A\n");
  out << "  seating velocity nu+ = " << text(S.nu_plus) << "\n";
  for (int i = 0; i < scene.num_contacts(); ++i)
    out << "  fixel " << i << ": v_t = " << internal::readable(S.tangential_velocity[i]) << " m/s"
        << (S.sliding[i] > 0   ? ", slides +t"
            : S.sliding[i] < 0 ? ", slides -t"
                               : ", sticks")
        << "\n";
  for (std::size_t k = 0; k < S.generators.size(); ++k)
    out << "  generator g" << k << " (fixel " << S.generator_fixel[k] << ") = " << text(S.generators[k]) << "\n";
  out << "  S = apex - cone(g):  apex = " << text(S.apex) << "\n";
  out << "  facets (S is where all hold):\n";
  for (const auto& h : S.halfspaces) out << "    " << halfspace_text(h) << "\n";
  if (report.impulse) {
    const bool in = report.impulse->in_S;
    out << "Impulse p = " << text(report.impulse->impulse) << " is " << (in ? "IN" : "NOT in") << " S";
    out << (in ? " (one-step: can seat): some outcome of the one-step model seats the part.\n"
               : " (one-step: cannot seat): no outcome of the one-step model seats the part.\n");
    out << outcomes_warning(report.impulse->outcomes);
    if (!report.impulse->y) return out.str();  // eq. 27 needs every fixel sliding
    const VectorQ& y = *report.impulse->y;
    out << "  eq. (27) y = K^-1 (P p + a):\n";
    for (int k = 0; k < y.size(); ++k)
      out << "    " << report.impulse->y_names[k] << " = " << internal::readable(y[k]) << (y[k] < 0 ? "   < 0" : "")
          << "\n";
  }
  return out.str();
}

std::string simulation_json(const Scene& scene, const Simulation& sim, const OutcomeCount* first_step) {
  json doc;
  doc["scene"] = scene.name;
  doc["seated"] = sim.seated;
  if (first_step) doc["outcomes_of_first_step"] = {{"total", first_step->total}, {"seating", first_step->seating}};
  doc["steps"] = json::array();
  for (const auto& s : sim.steps)
    doc["steps"].push_back({{"q", exact_json(s.q)},
                            {"velocity", exact_json(s.velocity)},
                            {"gaps", exact_json(s.gaps)},
                            {"p_n", exact_json(s.p_n)},
                            {"p_f", exact_json(s.p_f)},
                            {"pivots", s.pivots}});
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

std::string simulation_text(const Scene& scene, const Simulation& sim, const OutcomeCount* first_step) {
  std::ostringstream out;
  out << "Simulation of scene \"" << scene.name << "\", " << sim.steps.size()
      << " step(s) of h = " << internal::readable(scene.time_step)
      << " s, exact Lemke per step (one outcome per step: the one Lemke finds)\n";
  out << "  units: q in m, m, rad; velocity in m/s, m/s, rad/s; gaps in m; impulses in N*s\n";
  for (std::size_t k = 0; k < sim.steps.size(); ++k) {
    const auto& s = sim.steps[k];
    out << "  step " << k + 1 << ": q = " << text(s.q) << ", velocity = " << text(s.velocity) << "\n";
    out << "          gaps = " << text(s.gaps) << ", p_n = " << text(s.p_n) << ", p_f = " << text(s.p_f) << "\n";
  }
  if (first_step) out << outcomes_warning(*first_step);
  out << (sim.seated ? "SEATED: every gap is exactly 0 after the last step.\n"
                     : "NOT seated: some gap is open after the last step.\n");
  return out.str();
}

namespace {
json mode_names(const std::vector<ContactMode>& modes) {
  json out = json::array();
  for (auto m : modes) out.push_back(to_string(m));
  return out;
}
}  // namespace

std::string outcomes_json(const Scene& scene, const VectorQ& p_ext, const std::vector<Outcome>& outcomes) {
  json doc;
  doc["scene"] = scene.name;
  doc["impulse"] = exact_json(p_ext);
  doc["solutions"] = json::array();
  int seating = 0;
  for (const auto& o : outcomes) {
    seating += o.seated ? 1 : 0;
    doc["solutions"].push_back({{"seated", o.seated},
                                {"modes", mode_names(o.modes)},
                                {"velocity", exact_json(o.velocity)},
                                {"gaps", exact_json(o.gaps)},
                                {"p_n", exact_json(o.p_n)},
                                {"p_t", exact_json(o.p_t)},
                                {"isolated", o.isolated}});
  }
  doc["seating"] = seating;
  doc["non_seating"] = static_cast<int>(outcomes.size()) - seating;
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

std::string outcomes_text(const Scene& scene, const VectorQ& p_ext, const std::vector<Outcome>& outcomes) {
  std::ostringstream out;
  bool family = false;
  for (const auto& o : outcomes) family = family || !o.isolated;
  out << "Outcomes of one step of scene \"" << scene.name << "\" under p = " << text(p_ext) << " N*s ("
      << outcomes.size() << " distinct, by exact enumeration of contact modes"
      << (family ? "; those marked lie on a family of infinitely many outcomes" : "") << ")\n";
  out << "  units: velocity in m/s, m/s, rad/s; gaps in m; impulses in N*s\n";
  int seating = 0;
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const auto& o = outcomes[k];
    seating += o.seated ? 1 : 0;
    out << "  " << k + 1 << ". " << (o.seated ? "SEATS  " : "OPEN GAP") << "  modes";
    for (auto m : o.modes) out << " " << to_string(m);
    out << (o.isolated ? "" : "  (one of a family)") << "\n";
    out << "     velocity = " << text(o.velocity) << ", gaps = " << text(o.gaps) << "\n";
    out << "     p_n = " << text(o.p_n) << ", p_t = " << text(o.p_t) << "\n";
  }
  out << seating << " seating, " << outcomes.size() - seating << " non-seating"
      << (family ? " (of the listed outcomes: a family counts once per listed point of it)" : "") << "\n";
  return out.str();
}

std::string verification_text(const std::vector<VerificationCheck>& checks) {
  std::ostringstream out;
  int failed = 0;
  for (const auto& c : checks) {
    out << (c.passed ? "PASS " : "FAIL ") << c.name << ": " << c.detail << "\n";
    failed += c.passed ? 0 : 1;
  }
  out << (checks.size() - failed) << " passed, " << failed << " failed\n";
  return out.str();
}

std::string verification_json(const std::vector<VerificationCheck>& checks) {
  json doc;
  doc["checks"] = json::array();
  long passed = 0;
  for (const auto& c : checks) {
    doc["checks"].push_back({{"name", c.name}, {"passed", c.passed}, {"detail", c.detail}});
    passed += c.passed ? 1 : 0;
  }
  doc["passed"] = passed == static_cast<long>(checks.size());
  doc["passed_count"] = passed;  // the text's "N passed, M failed"
  doc["failed_count"] = static_cast<long>(checks.size()) - passed;
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

}  // namespace fixel