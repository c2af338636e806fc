// `fixel dump --off DIR`: OFF/OBJ files of S, G's pieces, the outline and
// the segment cones (docs/formats.md).
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/json_exact.h"
#include "fixel/internal/off_sidecar.h"
#include "fixel/internal/seating_sets_check.h"
#include "fixel/io.h"
#include "fixel/off_io.h"
#include "fixel/wrench_cone.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

using internal::exact_json;

json box_json(const Box& box) { return {{"lo", exact_json(box.lo)}, {"hi", exact_json(box.hi)}}; }

void append(std::vector<std::string>& to, const std::vector<std::string>& paths) {
  to.insert(to.end(), paths.begin(), paths.end());
}

}  // namespace

std::vector<std::string> dump_off(const Scene& scene, const SeatingSet& S, const std::string& dir,
                                  const Rational& length, const GuaranteedSet* G) {
  internal::check_seating_sets_of(scene, S, G);
  internal::make_output_folder(dir, "dump_off(directory)");
  const Box box = seating_dump_box(S, length);
  std::vector<Halfspace> hs = S.halfspaces;
  for (const auto& h : box.halfspaces()) hs.push_back(h);
  const std::string path = (std::filesystem::path(dir) / "seating_set.off").string();
  const char* space = S.dof == 2 ? "impulse (px, py), drawn in the plane z = 0" : "impulse (px, py, ptheta)";
  std::vector<std::string> written;
  append(written, internal::write_off_with_sidecar(
                      path, hs, S.dof,
                      {{"what", "seating_set"},
                       {"description", "the seating impulse set S, clipped to a box"},
                       {"scene", scene.name},
                       {"space", space},
                       {"apex", exact_json(S.apex)},
                       {"length", to_string(length)},
                       {"box", box_json(box)},
                       {"box_rule", "the smallest box holding the apex and apex + length * r for every ray r"},
                       {"coordinates", "the OFF vertices are rounded to double for display"}},
                      "dump_off(directory)"));
  if (G) {
    for (std::size_t k = 0; k < G->pieces.size(); ++k) {
      const std::string piece_path =
          (std::filesystem::path(dir) / ("guaranteed_" + std::to_string(k) + ".off")).string();
      std::vector<Halfspace> rows = G->pieces[k].closed;
      for (const auto& h : G->pieces[k].strict) rows.push_back(h);  // the closure
      for (const auto& h : box.halfspaces()) rows.push_back(h);
      append(written, internal::write_off_with_sidecar(
                          piece_path, rows, S.dof,
                          {{"what", "guaranteed_piece"},
                           {"description", "piece " + std::to_string(k) +
                                               " of the guaranteed set G: its closure (strict "
                                               "rows drawn as closed), clipped to the box"},
                           {"scene", scene.name},
                           {"space", space},
                           {"piece", k},
                           {"dimension", k < G->dimensions.size() ? json(G->dimensions[k]) : json(nullptr)},
                           {"strict_rows", G->pieces[k].strict.size()},
                           {"box", box_json(box)},
                           {"coordinates", "the OFF vertices are rounded to double for display"}},
                          "dump_off(directory)"));
    }
  }
  if (!scene.body.boundary) return written;

  const Boundary& boundary = *scene.body.boundary;
  const std::string obj_path = (std::filesystem::path(dir) / "boundary.obj").string();
  internal::write_file(obj_path, "dump_off(directory)", [&](std::ostream& obj) {
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
  });
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
        json gens = json::array();
        for (const auto& g : cone->generators) gens.push_back(exact_json(g));
        append(written, internal::write_off_with_sidecar(
                            cone_path, hs, 3,
                            {{"what", "wrench_cone"},
                             {"description", "the wrench cone of one Bezier piece, clipped to the box"},
                             {"scene", scene.name},
                             {"space", "wrench (fx, fy, moment about the centre of mass)"},
                             {"curve", piece.curve},
                             {"u0", to_string(piece.u0)},
                             {"u1", to_string(piece.u1)},
                             {"family", to_string(family)},
                             {"method", method == ConeMethod::kTight ? "tight" : "paper"},
                             {"generators", gens},
                             {"box", box_json(cube)},
                             {"coordinates", "the OFF vertices are rounded to double for display"}},
                            "dump_off(directory)"));
      }
  }
  return written;
}

}  // namespace fixel
