// The sustained-push checks of `fixel verify` (docs/theory.md §10).
#include <functional>

#include "fixel/approach.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/scene_json.h"
#include "fixel/sustained.h"
#include "fixel/verify.h"

namespace fixel::internal {

// The check runner of verify.cpp (a check returns "" or what differed).
VerificationCheck run_check(const std::string& name, const std::string& what,
                            const std::function<std::string()>& check);

namespace {

// The square [−1, 1]² with fixels at (−1, y0) and (x1, −1), (x2, −1).
const char* kSquare = R"({"name": "square", "time_step": "1",
  "body": {"dof": "3", "mass": "1", "center_of_mass": ["0", "0"],
           "boundary": [{"type": "polyline", "points": [["-1","-1"], ["1","-1"], ["1","1"], ["-1","1"], ["-1","-1"]]}]},
  "fixels": [{"point": ["-1", "Y0"], "normal": ["1", "0"], "mu": "MU", "gap": "G0"},
             {"point": ["X1", "-1"], "normal": ["0", "1"], "mu": "MU", "gap": "G1"},
             {"point": ["X2", "-1"], "normal": ["0", "1"], "mu": "MU", "gap": "G2"}]})";

// The bundled polygon part (data/scenes/polygon.json), kept here so that an
// installed `fixel verify` needs no data files.
const char* kPolygon = R"({"name": "polygon", "time_step": "1",
  "body": {"dof": 3, "boundary": [{"type": "polyline",
    "points": [["-1", "-1"], ["3/2", "-1"], ["3/2", "1/2"], ["1/4", "3/2"], ["-1", "1/2"], ["-1", "-1"]]}]},
  "fixels": [{"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
             {"point": ["-1/2", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
             {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "3/20"}]})";

std::string square(const std::string& mu, const std::string& y0, const std::string& x1, const std::string& x2,
                   const std::string& g0, const std::string& g1, const std::string& g2) {
  std::string s = kSquare;
  auto put = [&](const std::string& key, const std::string& value) {
    for (auto at = s.find(key); at != std::string::npos; at = s.find(key)) s.replace(at, key.size(), value);
  };
  put("MU", mu), put("Y0", y0), put("X1", x1), put("X2", x2), put("G0", g0), put("G1", g1), put("G2", g2);
  return s;
}

// A wrench strictly inside a piece: the sum of its closure's rays.
VectorQ inside(const AlgebraicCone& piece) {
  VectorQ w = VectorQ::Zero(3);
  for (const auto& r : piece.rays)
    for (int k = 0; k < 3; ++k) w[k] += r[k].a;  // rational pieces only (θ* = 0 scenes)
  return w;
}

}  // namespace

std::vector<VerificationCheck> sustained_checks() {
  std::vector<VerificationCheck> out;
  out.push_back(
      run_check("sustained.seat", "a square turned by cos 24/25, sin 7/25 and moved by (-1/10, -1/5): q* exact", [] {
        const Scene scene = parse_scene(square("0", "-12/25", "-3/10", "33/50", "3/50", "3/10", "1/50"), "square");
        const SeatedPose q = seated_pose(scene);
        const std::array<Rational, 4> want = {Rational(-1, 10), Rational(-1, 5), Rational(24, 25), Rational(7, 25)};
        for (int k = 0; k < 4; ++k)
          if ((*q.exact)[k].b != 0 || (*q.exact)[k].a != want[k])
            return "component " + std::to_string(k) + " is " + (*q.exact)[k].text();
        return std::string();
      }));
  out.push_back(run_check("sustained.residual", "polygon: R (g_i - c) + c + t = f_i exactly at q* (in Q(sqrt d))", [] {
    const Scene scene = parse_scene(kPolygon, "polygon");
    const SeatedPose q = seated_pose(scene);
    const auto& e = *q.exact;
    const Q2 tx = from_public(e[0]), ty = from_public(e[1]), c = from_public(e[2]), s = from_public(e[3]);
    if (sign(c * c + s * s - Q2(1)) != 0) return std::string("cos^2 + sin^2 != 1");
    const Vec2& cm = scene.body.p_AoCm_A;
    for (int i = 0; i < 3; ++i) {
      const Fixel& f = scene.fixels[i];
      const Q2 gx = from_public(q.p_BoG_B[i][0]) - Q2(cm.x), gy = from_public(q.p_BoG_B[i][1]) - Q2(cm.y);
      const Q2 wx = c * gx - s * gy + Q2(cm.x) + tx, wy = s * gx + c * gy + Q2(cm.y) + ty;
      if (sign(wx - Q2(f.p_AoF_A.x - f.gap * f.n_A.x)) != 0 || sign(wy - Q2(f.p_AoF_A.y - f.gap * f.n_A.y)) != 0)
        return "fixel " + std::to_string(i) + " is not at its seat";
    }
    return std::string();
  }));
  out.push_back(
      run_check("sustained.frictionless", "square, mu = 0: J is the open cone {-w in int cone(W_n)}, one piece", [] {
        const SustainedSet J = sustained_set(parse_scene(square("0", "0", "-1/2", "1/2", "0", "0", "0"), "square"));
        if (J.pieces.size() != 1) return "J has " + std::to_string(J.pieces.size()) + " pieces";
        // −W_n = rows (−1, 0, 0), (0, −1, 1/2), (0, −1, −1/2): their sum is inside, each column is on the boundary.
        if (!J.contains(VectorQ(Eigen::Matrix<Rational, 3, 1>(-1, -2, 0)))) return std::string("(-1, -2, 0) not in J");
        if (J.contains(VectorQ(Eigen::Matrix<Rational, 3, 1>(0, -2, 0)))) return std::string("(0, -2, 0) is in J");
        return std::string();
      }));
  out.push_back(run_check("sustained.monotone", "square: every piece of J(mu = 1/5) lies in J(mu = 1/10)", [] {
    const SustainedSet J1 = sustained_set(parse_scene(square("1/10", "0", "-1/2", "1/2", "0", "0", "0"), "square"));
    const SustainedSet J2 = sustained_set(parse_scene(square("1/5", "0", "-1/2", "1/2", "0", "0", "0"), "square"));
    if (J2.empty) return std::string("J(1/5) is empty");
    for (const auto& p : J2.pieces)
      if (!J1.contains(inside(p))) return std::string("a wrench of J(1/5) is not in J(1/10)");
    return std::string();
  }));
  // The polygon's seat turns by an irrational angle, where the contact-mode
  // enumeration cannot run: its strong stability is the theorem's
  // (docs/theory.md §10.3), so the check says no more than non-empty.
  out.push_back(run_check("sustained.polygon", "bundled polygon: J is non-empty", [] {
    const SustainedSet J = sustained_set(parse_scene(kPolygon, "polygon"));
    if (J.empty) return "J is empty: " + J.empty_reason;
    return std::string();
  }));
  // sustained.seat's hand-built seat, turned by cos θ = 24/25, sin θ = 7/25
  // (rational), with friction: strong stability checked by the second
  // method, every contact mode of the step LCP at the seat, once per piece.
  out.push_back(run_check(
      "sustained.stability",
      "square seated at a rational rotation: every contact mode keeps the part at rest, one wrench per piece of J", [] {
        const SustainedSet J =
            sustained_set(parse_scene(square("1/10", "-12/25", "-3/10", "33/50", "3/50", "3/10", "1/50"), "square"));
        if (J.empty) return "J is empty: " + J.empty_reason;
        if (J.stability_checks != static_cast<int>(J.pieces.size()))
          return std::to_string(J.stability_checks) + " wrenches checked for " + std::to_string(J.pieces.size()) +
                 " pieces";
        if (!J.strongly_stable) return std::string("an outcome moves: not strongly stable");
        return std::string();
      }));
  out.push_back(run_check(
      "sustained.approach",
      "polygon: w = (-1/2, -9/10, -3/5) is in J, and fixels 0, 2 hold it at theta = 0 (an exact LP), so not in J'", [] {
        const Scene scene = parse_scene(kPolygon, "polygon");
        const SustainedSet J = sustained_set(scene);
        const ApproachSet A = approach_set(scene, J);
        const VectorQ w = (VectorQ(3) << Rational(-1, 2), Rational(-9, 10), Rational(-3, 5)).finished();
        if (!A.decided || !A.on_edges) return "J' not decided or empty: " + A.undecided_reason + A.edge_reason;
        if (!J.contains(w)) return std::string("w is not in J");
        // At θ = 0 fixels 0 (gap 1/10, left edge x = -1) and 2 (gap 3/20, bottom
        // edge y = -1) touch when the part moves by (-1/10, -3/20): contacts
        // (-1, 3/20) and (11/10, -1) in frame B; is -w in FC_0 + FC_2?
        const Vec2& c = scene.body.p_AoCm_A;
        const Vec2 g0{Rational(-1), Rational(3, 20)}, g2{Rational(11, 10), Rational(-1)};
        const Rational mu(1, 10);
        std::vector<VectorQ> gens;
        for (int s : {1, -1}) {
          const Vec2 b0{Rational(1), s * mu}, b2{-s * mu, Rational(1)};
          gens.push_back((VectorQ(3) << b0.x, b0.y, (g0.x - c.x) * b0.y - (g0.y - c.y) * b0.x).finished());
          gens.push_back((VectorQ(3) << b2.x, b2.y, (g2.x - c.x) * b2.y - (g2.y - c.y) * b2.x).finished());
        }
        std::vector<LinearConstraint> rows;
        for (int k = 0; k < 3; ++k) {
          VectorQ a(4);
          for (int g = 0; g < 4; ++g) a[g] = gens[g][k];
          rows.push_back({a, Relation::kEqual, -w[k]});
        }
        for (int g = 0; g < 4; ++g) {
          VectorQ a = VectorQ::Zero(4);
          a[g] = 1;
          rows.push_back({a, Relation::kGreaterEqual, Rational(0)});
        }
        if (solve_lp(4, rows).status != LpStatus::kOptimal) return std::string("the LP finds no hold at theta = 0");
        ApproachHold hold;
        if (A.why_not(w, &hold).empty()) return std::string("w is in J'");
        if (hold.fixels != std::array<int, 2>{0, 2}) return std::string("another pair holds it");
        return std::string();
      }));
  return out;
}

}  // namespace fixel::internal
