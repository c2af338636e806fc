// `fixel dump --off DIR`: OFF/OBJ files of S, G's pieces, the outline and
// the segment cones (docs/formats.md).
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/io.h"
#include "fixel/off_io.h"
#include "fixel/wrench_cone.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

std::string text(const VectorQ& v) {
  std::string s = "(";
  for (int k = 0; k < v.size(); ++k) s += (k ? ", " : "") + to_string(v[k]);
  return s + ")";
}

}  // namespace

std::vector<std::string> dump_off(const Scene& scene, const SeatingSet& S, const std::string& dir,
                                  const Rational& length, const GuaranteedSet* G) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("dump_off(directory)", dir, "cannot be created: " + ec.message());
  const Box box = seating_dump_box(S, length);
  std::vector<Halfspace> hs = S.halfspaces;
  for (const auto& h : box.halfspaces()) hs.push_back(h);
  const std::string path = (std::filesystem::path(dir) / "seating_set.off").string();
  std::ofstream out(path);
  if (!out) throw InputError("dump_off(directory)", path, "cannot be written");
  write_polytope_off(out, hs, S.dof,
                     {"fixel: seating impulse set S of scene \"" + scene.name + "\"" +
                          (S.dof == 2 ? " (dof 2, drawn in the plane z = 0)" : ""),
                      "clipped to the box " + box.describe(),
                      "(the box holds the apex and apex + " + to_string(length) + " * r for every ray r)",
                      "apex " + text(S.apex) + "; coordinates below are rounded to double for display"});
  if (!out) throw InputError("dump_off(directory)", path, "could not be written completely");
  std::vector<std::string> written = {path};
  if (G) {
    for (std::size_t k = 0; k < G->pieces.size(); ++k) {
      const std::string piece_path =
          (std::filesystem::path(dir) / ("guaranteed_" + std::to_string(k) + ".off")).string();
      std::ofstream piece_out(piece_path);
      if (!piece_out) throw InputError("dump_off(directory)", piece_path, "cannot be written");
      std::vector<Halfspace> rows = G->pieces[k].closed;
      for (const auto& h : G->pieces[k].strict) rows.push_back(h);  // the closure
      for (const auto& h : box.halfspaces()) rows.push_back(h);
      write_polytope_off(
          piece_out, rows, S.dof,
          {"fixel: piece " + std::to_string(k) + " of the guaranteed set G of scene \"" + scene.name + "\"",
           "its closure (" + std::to_string(G->pieces[k].strict.size()) +
               " strict rows drawn as closed), clipped to the box " + box.describe()});
      written.push_back(piece_path);
    }
  }
  if (!scene.body.boundary) return written;

  const Boundary& boundary = *scene.body.boundary;
  const std::string obj_path = (std::filesystem::path(dir) / "boundary.obj").string();
  std::ofstream obj(obj_path);
  if (!obj) throw InputError("dump_off(directory)", obj_path, "cannot be written");
  obj << "# fixel: boundary of scene \"" << scene.name << "\", 32 samples per Bezier piece (display only)\n";
  obj.precision(17);
  int count = 0;
  for (const auto& piece : boundary.pieces) {
    obj << "# curve " << piece.curve << ", u in [" << to_string(piece.u0) << ", " << to_string(piece.u1) << "]\n";
    for (int k = 0; k < 32; ++k) {
      const Vec2 p = piece.point(Rational(k, 32));
      obj << "v " << to_double(p.x) << " " << to_double(p.y) << " 0\n";
      ++count;
    }
  }
  obj << "l";
  for (int k = 1; k <= count; ++k) obj << " " << k;
  obj << " 1\n";
  written.push_back(obj_path);

  std::vector<EdgeFamily> families = {EdgeFamily::kNormal};
  if (scene.pusher_mu > 0) families = {EdgeFamily::kMinus, EdgeFamily::kPlus};
  Box cube{VectorQ::Constant(3, Rational(-1)), VectorQ::Constant(3, Rational(1))};
  for (std::size_t k = 0; k < boundary.pieces.size(); ++k) {
    const BezierPiece& piece = boundary.pieces[k];
    const SegmentBounds bounds = segment_bounds(piece);
    for (auto family : families)
      for (auto method : {ConeMethod::kTight, ConeMethod::kPaper}) {
        const auto cone = segment_wrench_cone(bounds, scene.body.p_AoCm_A, family, scene.pusher_mu, method);
        if (!cone) continue;
        std::vector<Halfspace> hs;
        for (const auto& a : cone->facets) hs.push_back({a, Rational(0)});
        for (const auto& h : cube.halfspaces()) hs.push_back(h);
        const std::string name =
            "segment_" + std::to_string(k) + "_" +
            (family == EdgeFamily::kNormal ? "normal" : (family == EdgeFamily::kMinus ? "minus" : "plus")) + "_" +
            (method == ConeMethod::kTight ? "tight" : "paper") + ".off";
        const std::string cone_path = (std::filesystem::path(dir) / name).string();
        std::ofstream cone_out(cone_path);
        if (!cone_out) throw InputError("dump_off(directory)", cone_path, "cannot be written");
        std::string gens;
        for (const auto& g : cone->generators) gens += text(g) + " ";
        write_polytope_off(
            cone_out, hs, 3,
            {"fixel: wrench cone of curve " + std::to_string(piece.curve) + ", u in [" + to_string(piece.u0) + ", " +
                 to_string(piece.u1) + "], family " + to_string(family) + ", " +
                 (method == ConeMethod::kTight ? "tight" : "paper") + " cone",
             "wrench space (fx, fy, moment about the centre of mass), clipped to the box " + cube.describe(),
             "generators " + gens});
        written.push_back(cone_path);
      }
  }
  return written;
}

}  // namespace fixel
