#include "fixel/off_io.h"

#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost_mp.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/json_approx.h"
#include "fixel/internal/off_sidecar.h"

namespace fixel {

namespace {

using ExactKernel = CGAL::Simple_cartesian<Rational>;  // exact hull predicates
using DisplayPoint = CGAL::Simple_cartesian<double>::Point_3;

// Visits every k-subset of {0..n-1}.
template <typename F>
void for_each_subset(int n, int k, F&& visit) {
  std::vector<int> idx(k);
  for (int i = 0; i < k; ++i) idx[i] = i;
  while (k <= n) {
    visit(idx);
    int i = k - 1;
    while (i >= 0 && idx[i] == n - k + i) --i;
    if (i < 0) return;
    ++idx[i];
    for (int j = i + 1; j < k; ++j) idx[j] = idx[j - 1] + 1;
  }
}

}  // namespace

std::vector<Halfspace> Box::halfspaces() const {
  std::vector<Halfspace> out;
  for (int k = 0; k < lo.size(); ++k) {
    out.push_back({VectorQ::Unit(lo.size(), k), lo[k]});
    out.push_back({VectorQ(-VectorQ::Unit(lo.size(), k)), Rational(-hi[k])});
  }
  return out;
}

std::string Box::describe() const {
  std::string s;
  for (int k = 0; k < lo.size(); ++k) s += (k ? " x [" : "[") + to_string(lo[k]) + ", " + to_string(hi[k]) + "]";
  return s;
}

Box seating_dump_box(const SeatingSet& S, const Rational& length) {
  if (length <= 0) throw InputError("dump_off(length)", to_string(length), "must be > 0");
  Box box{S.apex, S.apex};
  for (const auto& r : S.rays) {
    const VectorQ tip = S.apex + length * r;
    for (int k = 0; k < S.dof; ++k) {
      box.lo[k] = std::min(box.lo[k], tip[k]);
      box.hi[k] = std::max(box.hi[k], tip[k]);
    }
  }
  return box;
}

std::vector<VectorQ> polytope_vertices(const std::vector<Halfspace>& halfspaces, int dim) {
  std::vector<VectorQ> vertices;
  const int n = static_cast<int>(halfspaces.size());
  for_each_subset(n, dim, [&](const std::vector<int>& idx) {
    MatrixQ A(dim, dim);
    VectorQ c(dim);
    for (int r = 0; r < dim; ++r) {
      A.row(r) = halfspaces[idx[r]].a.transpose();
      c[r] = halfspaces[idx[r]].c;
    }
    const auto lu = internal::exact_lu(A);
    if (!lu.isInvertible()) return;
    const VectorQ v = lu.solve(c);
    for (const auto& h : halfspaces)
      if (!h.contains(v)) return;
    for (const auto& u : vertices)
      if (u == v) return;
    vertices.push_back(v);
  });
  return vertices;
}

std::size_t write_polytope_off(std::ostream& out, const std::vector<Halfspace>& halfspaces, int dim) {
  if (dim != 2 && dim != 3) throw InputError("dim", std::to_string(dim), "must be 2 or 3");
  const std::vector<VectorQ> vertices = polytope_vertices(halfspaces, dim);
  std::vector<DisplayPoint> points;
  std::vector<std::vector<std::size_t>> faces;
  if (dim == 3 && vertices.size() >= 3) {
    std::vector<ExactKernel::Point_3> exact;
    for (const auto& v : vertices) exact.emplace_back(v[0], v[1], v[2]);
    CGAL::Surface_mesh<ExactKernel::Point_3> mesh;
    CGAL::convex_hull_3(exact.begin(), exact.end(), mesh);
    for (auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      points.emplace_back(to_double(p.x()), to_double(p.y()), to_double(p.z()));
    }
    for (auto f : mesh.faces()) {
      std::vector<std::size_t> face;
      for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) face.push_back(v.idx());
      faces.push_back(face);
    }
  } else if (dim == 2 && !vertices.empty()) {
    std::vector<ExactKernel::Point_2> exact, hull;
    for (const auto& v : vertices) exact.emplace_back(v[0], v[1]);
    CGAL::convex_hull_2(exact.begin(), exact.end(), std::back_inserter(hull));
    std::vector<std::size_t> face;
    for (const auto& p : hull) {
      face.push_back(points.size());
      points.emplace_back(to_double(p.x()), to_double(p.y()), 0.0);
    }
    if (face.size() >= 3) faces.push_back(face);
  } else {
    for (const auto& v : vertices)
      points.emplace_back(to_double(v[0]), to_double(v[1]), dim == 3 ? to_double(v[2]) : 0.0);
  }
  std::ostringstream off;
  off.precision(17);
  if (!CGAL::IO::write_OFF(off, points, faces))
    throw InternalError("CGAL::IO::write_OFF failed on an in-memory stream");
  out << off.str();
  return points.size();
}

namespace internal {

std::string sidecar_path(const std::string& off_path) {
  return std::filesystem::path(off_path).replace_extension(".json").string();
}

std::vector<std::string> write_off_with_sidecar(const std::string& off_path, const std::vector<Halfspace>& halfspaces,
                                                int dim, const nlohmann::ordered_json& meta, const std::string& field) {
  std::size_t vertices = 0;
  write_file(off_path, field, [&](std::ostream& out) { vertices = write_polytope_off(out, halfspaces, dim); });
  std::vector<VectorQ> exact = polytope_vertices(halfspaces, dim);
  std::vector<VectorQ> directions;
  for (std::size_t k = 1; k < exact.size(); ++k) directions.push_back(VectorQ(exact[k] - exact[0]));
  nlohmann::ordered_json doc;
  doc["format"] = "fixel OFF sidecar 1";
  doc["off"] = std::filesystem::path(off_path).filename().string();
  doc["vertices"] = vertices;
  // The drawn (clipped) polytope's dimension: -1 empty, 0 a point, 1 a segment, ...
  doc["drawn_dimension"] = exact.empty() ? -1 : internal::exact_rank(directions, dim);
  for (const auto& [key, value] : meta.items()) doc[key] = value;
  internal::add_approx(doc);
  const std::string json_path = sidecar_path(off_path);
  write_file(json_path, field, [&](std::ostream& side) { side << doc.dump(2) << "\n"; });
  return {off_path, json_path};
}

}  // namespace internal

}  // namespace fixel
