/// @file
/// Fixture design (docs/design.md): candidates, the thread-pool run, the
/// batch functions that fixel.design maps over a Dask cluster and the
/// bounded search that orders them. Candidates
/// cross as (curve, u) with u exact text, options as a dict of exact texts,
/// results as exact texts or the `fixel design --json` document.

#include <memory>
#include <optional>
#include <string>

#include "bindings.h"
#include "fixel/design.h"
#include "fixel/design_search.h"
#include "fixel/progress.h"

namespace fixel::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;
using CandidateList = std::vector<std::pair<int, std::string>>;

std::vector<DesignCandidate> candidates_of(const Scene& part, const CandidateList& list) {
  if (list.size() > 10000)
    throw InputError("candidates", std::to_string(list.size()) + " entries", "is more than 10000");
  std::vector<DesignCandidate> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string field = "candidates[" + std::to_string(i) + "]";
    out.push_back(candidate_at(part, list[i].first, parse_rational(list[i].second, field + ".u"), field));
  }
  check_candidate_list(out);
  return out;
}

CandidateList list_of(const std::vector<DesignCandidate>& cands) {
  CandidateList out;
  for (const auto& c : cands) out.emplace_back(c.curve, to_string(c.u));
  return out;
}

std::string text_item(const py::dict& d, const char* key, const char* fallback) {
  if (!d.contains(key) || d[key].is_none()) return fallback;
  return py::str(d[key]);
}

// {"push", "resolution", "mu", "mu_hi", "pusher_mu", "pusher_mu_lo", "gap", "top", "jobs", "bound"}.
DesignOptions options_of(const py::dict& d) {
  DesignOptions o;
  const std::string push = text_item(d, "push", "sustained");
  if (push != "sustained" && push != "step") throw InputError("push", push, "must be sustained or step");
  o.push = push == "step" ? DesignPush::kStep : DesignPush::kSustained;
  o.resolution = parse_rational(text_item(d, "resolution", "1/256"), "resolution");
  o.mu = parse_rational(text_item(d, "mu", "1/10"), "mu");
  if (d.contains("mu_hi") && !d["mu_hi"].is_none()) o.mu_hi = parse_rational(py::str(d["mu_hi"]), "mu");
  o.pusher_mu = parse_rational(text_item(d, "pusher_mu", "0"), "pusher_mu");
  if (d.contains("pusher_mu_lo") && !d["pusher_mu_lo"].is_none())
    o.pusher_mu_lo = parse_rational(py::str(d["pusher_mu_lo"]), "pusher_mu");
  o.gap = parse_rational(text_item(d, "gap", "0"), "gap");
  o.top = d.contains("top") ? d["top"].cast<int>() : 5;
  o.jobs = d.contains("jobs") && !d["jobs"].is_none() ? d["jobs"].cast<int>() : 0;
  o.bound = d.contains("bound") ? d["bound"].cast<bool>() : true;
  return o;
}

// A batch's answer: ([(i, j, k, index, score)], (singular, no_form_closure,
// j_empty, regions)).
py::tuple batch_tuple(const std::vector<DesignLayout>& best, const DesignStats& stats) {
  py::list layouts;
  for (const auto& l : best)
    layouts.append(py::make_tuple(l.fixels[0], l.fixels[1], l.fixels[2], l.index, to_string(l.score)));
  return py::make_tuple(layouts, py::make_tuple(stats.singular, stats.no_form_closure, stats.j_empty, stats.regions));
}

// A batch from Python: `score(part, candidates, options, stats)` (a
// design_batch call with its triples) with the GIL released.
template <class Score>
py::tuple run_batch(const ScenePtr& scene, const CandidateList& list, const py::dict& opts, Score&& score) {
  const Scene& s = checked(scene, "scene");
  const auto cands = candidates_of(s, list);
  const DesignOptions o = options_of(opts);
  DesignStats stats;
  std::vector<DesignLayout> best;
  {
    py::gil_scoped_release release;
    best = score(s, cands, o, stats);
  }
  return batch_tuple(best, stats);
}

using TopList = std::vector<std::pair<long, std::string>>;

std::vector<DesignLayout> layouts_of(const TopList& top) {
  std::vector<DesignLayout> out(top.size());
  for (std::size_t k = 0; k < top.size(); ++k) {
    out[k].index = top[k].first;
    out[k].score = parse_rational(top[k].second, "top[" + std::to_string(k) + "].score");
  }
  return out;
}

struct SearchBox {
  DesignSearch search;
};

}  // namespace

void bind_design(py::module_& m) {
  m.def("design_candidates", [](const ScenePtr& scene, const std::optional<std::string>& spacing) {
    const Scene& s = checked(scene, "scene");
    std::optional<Rational> sp;
    if (spacing) sp = parse_rational(*spacing, "spacing");
    return list_of(boundary_candidates(s, sp));
  });
  m.def("design_check_candidates", [](const ScenePtr& scene, const CandidateList& list) {
    return list_of(candidates_of(checked(scene, "scene"), list));
  });
  m.def("design_load_candidates", [](const ScenePtr& scene, const std::string& path) {
    return list_of(load_candidates(checked(scene, "scene"), path));
  });
  m.def("design_candidate", [](const ScenePtr& scene, int curve, const std::string& u) {
    const DesignCandidate c = candidate_at(checked(scene, "scene"), curve, parse_rational(u, "u"), "candidate");
    return py::make_tuple(std::vector<std::string>{to_string(c.point.x), to_string(c.point.y)},
                          std::vector<std::string>{to_string(c.normal.x), to_string(c.normal.y)});
  });
  m.def("design_triples", [](long n) { return triple_count(n); });
  // The whole run on the C++ thread pool: the `fixel design --json` document.
  // `control` (or None) stops it and takes its progress.
  m.def(
      "design_json",
      [](const ScenePtr& scene, const CandidateList& list, const py::dict& opts, Control* control) {
        const ControlScope scope(run_control(control));  // exact steps inside poll it too
        const Scene& s = checked(scene, "scene");
        const auto cands = candidates_of(s, list);
        DesignOptions o = options_of(opts);
        o.control = run_control(control);
        py::gil_scoped_release release;
        const DesignResult r = design(s, cands, o);
        o.control = nullptr;
        return design_json(s, r, o, shipped_layout(s, o));
      },
      py::arg("scene"), py::arg("candidates"), py::arg("options"), py::arg("control") = nullptr);
  // One batch (idempotent): ([(i, j, k, index, score)], (singular,
  // no_form_closure, j_empty, regions)).
  m.def("design_batch", [](const ScenePtr& scene, const CandidateList& list, const py::dict& opts, long first,
                           long count) {
    return run_batch(scene, list, opts, [&](const Scene& s, const auto& c, const DesignOptions& o, DesignStats& st) {
      return design_batch(s, c, o, first, count, st);
    });
  });
  // The same for a list of triple indices (what DesignSearch hands out).
  m.def("design_batch_indices", [](const ScenePtr& scene, const CandidateList& list, const py::dict& opts,
                                   const std::vector<long>& indices) {
    return run_batch(scene, list, opts, [&](const Scene& s, const auto& c, const DesignOptions& o, DesignStats& st) {
      return design_batch(s, c, o, indices, st);
    });
  });
  // The bounded search, driven by fixel.design's Dask path: the best K so
  // far crosses as [(index, score text)], best first.
  py::class_<SearchBox>(m, "DesignSearch")
      .def(py::init([](const ScenePtr& scene, const CandidateList& list, const py::dict& opts) {
        const Scene& s = checked(scene, "scene");
        const auto cands = candidates_of(s, list);
        return std::make_unique<SearchBox>(SearchBox{DesignSearch(s, cands, options_of(opts))});
      }))
      .def("applies", [](const SearchBox& b) { return b.search.applies(); })
      .def("pilot", [](const SearchBox& b) { return b.search.pilot(); })
      .def("singular", [](const SearchBox& b) { return b.search.singular(); })
      .def("start",
           [](SearchBox& b, const TopList& top) {
             const auto layouts = layouts_of(top);
             py::gil_scoped_release release;
             return b.search.start(layouts);
           })
      .def("next", [](SearchBox& b, const TopList& top, long block) { return b.search.next(layouts_of(top), block); });
  // The report of a distributed run: re-scores the chosen triples (their
  // scores are a pure function of the triple), completes them and writes
  // the `fixel design --json` document with the run's counts.
  m.def("design_report",
        [](const ScenePtr& scene, const CandidateList& list, const py::dict& opts, const std::vector<long>& indices,
           const std::vector<long>& counts, double seconds, int jobs) {
          const Scene& s = checked(scene, "scene");
          const auto cands = candidates_of(s, list);
          DesignOptions o = options_of(opts);
          if (counts.size() != 4 && counts.size() != 5)
            throw InputError("counts", std::to_string(counts.size()), "must have 4 or 5 entries");
          py::gil_scoped_release release;
          DesignResult r;
          r.candidates = cands;
          r.stats.candidates = static_cast<long>(cands.size());
          r.stats.triples = triple_count(r.stats.candidates);
          r.stats.singular = counts[0];
          r.stats.no_form_closure = counts[1];
          r.stats.j_empty = counts[2];
          r.stats.regions = counts[3];
          if (counts.size() == 5) r.stats.bounded = counts[4];
          r.stats.seconds = seconds;
          r.stats.jobs = jobs;
          DesignStats ignored;
          for (long index : indices)
            for (auto& l : design_batch(s, cands, o, index, 1, ignored)) r.layouts.push_back(std::move(l));
          rank_layouts(r.layouts, o.top);
          complete_layouts(s, cands, o, r.layouts);
          r.no_layout = no_layout_reason(r.stats, r.layouts.size());
          return design_json(s, r, o, shipped_layout(s, o));
        });
  // A layout as a scene (fixel.design_scene): (Scene, largest rounding angle).
  m.def("design_scene", [](const ScenePtr& scene, const CandidateList& three, const py::dict& opts,
                           const std::string& score, int rank) {
    const Scene& s = checked(scene, "part");
    if (three.size() != 3)
      throw InputError("layout", std::to_string(three.size()) + " fixels", "must have three fixels");
    const auto cands = candidates_of(s, three);
    const DesignOptions o = options_of(opts);
    DesignLayout layout;
    layout.fixels = {0, 1, 2};
    layout.score = parse_rational(score, "score");
    double angle_error = 0;
    py::gil_scoped_release release;
    auto out = std::make_shared<Scene>(design_scene(s, cands, layout, rank, o, &angle_error));
    return std::make_pair(out, angle_error);
  });
  m.def("design_check_options",
        [](const ScenePtr& scene, const py::dict& opts) { check_design(checked(scene, "scene"), options_of(opts)); });
}

}  // namespace fixel::python
