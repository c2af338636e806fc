// fixel design: the best three fixels for one push (docs/design.md).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli.h"
#include "fixel/design.h"
#include "fixel/design_search.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"

namespace fixel::cli {
namespace {

struct DesignArgs {
  std::string scene_path, candidates = "boundary", spacing, push = "sustained", mu, pusher_mu, gap = "0",
                          resolution = "1/256", svg_path, scene_out;
  int top = 5, jobs = 0;
  bool json = false, exhaustive = false;
  RunOptions run;
};

bool g_bar_shown = false;

// A bar with the units done (pairs, triples bounded, layouts) and the
// rate, rewriting one line of stderr.
void show_design_progress(const char* task, long done, long total, const char* unit) {
  const double seconds = std::chrono::duration<double>(RunControl::Clock::now() - run_control()->start).count();
  constexpr int kWidth = 30;
  const int filled = total > 0 ? static_cast<int>(kWidth * done / total) : 0;
  std::string bar(filled, '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %ld/%ld %s, %.1f %s/s, %.0f s\033[K", task, bar.c_str(), done, total, unit,
               seconds > 0 ? done / seconds : 0.0, unit, seconds);
  std::fflush(stderr);
  g_bar_shown = true;
}

void end_bar() {
  if (g_bar_shown) std::fputs("\n", stderr);
  g_bar_shown = false;
}

DesignOptions design_options(const Scene& part, const DesignArgs& a) {
  DesignOptions o;
  o.push = a.push == "step" ? DesignPush::kStep : DesignPush::kSustained;
  o.resolution = parse_rational(a.resolution, "--resolution");
  if (!a.mu.empty()) {
    const auto mu = parse_rational_list(a.mu, "--mu");
    if (mu.size() > 2) throw InputError("--mu", a.mu, "must be M or lo,hi");
    o.mu = mu[0];
    if (mu.size() == 2) o.mu_hi = mu[1];
  } else if (!part.fixels.empty()) {  // the shipped fixels' largest μ, so that the comparison is fair
    o.mu = 0;
    for (const auto& f : part.fixels) o.mu = std::max(o.mu, f.mu_upper());
  }
  o.pusher_mu = a.pusher_mu.empty() ? part.pusher_mu_upper() : parse_pusher_mu(a.pusher_mu);
  // An interval's lower end goes into the layout's scene (--scene-out).
  if (a.pusher_mu.empty()) {
    if (part.pusher_mu_hi) o.pusher_mu_lo = part.pusher_mu;
  } else if (const auto both = parse_rational_list(a.pusher_mu, "--pusher-mu"); both.size() == 2) {
    o.pusher_mu_lo = both[0];
  }
  o.gap = parse_rational(a.gap, "--gap");
  o.top = a.top;
  o.jobs = a.jobs;
  o.bound = !a.exhaustive;
  o.control = run_control();
  return o;
}

int run_design(const DesignArgs& a) {
  arm_run_control(a.run);
  check_writable(a.svg_path, "--svg");
  check_writable(a.scene_out, "--scene-out", true);
  check_distinct_outputs(a.svg_path, "--svg", a.scene_out, "--scene-out");
  check_not_input(a.scene_path, a.svg_path, "--svg");
  check_not_input(a.scene_path, a.scene_out, "--scene-out");
  const Scene part = read_scene(a.scene_path);  // with the plain progress line
  if (run_control()->on_progress) run_control()->on_progress = show_design_progress;
  const DesignOptions o = design_options(part, a);
  check_design(part, o);  // every option checked before any work
  std::optional<Rational> spacing;
  if (!a.spacing.empty()) spacing = parse_rational(a.spacing, "--spacing");
  if (spacing && a.candidates != "boundary")
    throw InputError("--spacing", a.spacing, "applies to --candidates boundary only");
  const auto candidates =
      a.candidates == "boundary" ? boundary_candidates(part, spacing) : load_candidates(part, a.candidates);
  const long triples = triple_count(static_cast<long>(candidates.size()));
  if (o.push == DesignPush::kSustained && o.bound && triples > 32 && !DesignSearch(part, candidates, o).applies())
    std::cerr << "note: " << candidates.size() << " candidates: the pair bound applies up to 1024, so every one of the "
              << triples << " triples is scored (docs/design.md)\n";
  DesignResult r;
  try {
    r = design(part, candidates, o);
  } catch (...) {
    end_bar();
    throw;
  }
  end_bar();
  const auto shipped = shipped_layout(part, o);
  std::cout << (a.json ? design_json(part, r, o, shipped) : design_text(part, r, o, shipped));
  if (!a.svg_path.empty()) {
    write_design_svg(a.svg_path, part, r, o);
    if (!a.json) std::cout << "wrote " << a.svg_path << "\n";
  }
  if (!a.scene_out.empty()) {
    if (r.layouts.empty())
      throw InputError("--scene-out", a.scene_out, "was not written: there is no layout (" + r.no_layout + ")");
    double angle_error = 0;
    save_scene(design_scene(part, r.candidates, r.layouts[0], 1, o, &angle_error), a.scene_out);
    if (!a.json)
      std::cout << "wrote " << a.scene_out << " (layout #1 as a scene"
                << (angle_error > 0 ? "; normals rounded, marked off_boundary: see its description" : "") << ")\n";
  }
  return 0;
}

}  // namespace

Command add_design(CLI::App& app) {
  auto a = std::make_shared<DesignArgs>();
  auto* cmd = app.add_subcommand("design", "Fixture design: the three fixels whose pushing region is largest");
  cmd->add_option("part", a->scene_path, "Scene file with a boundary; its fixels may be empty; - reads standard input")
      ->required();
  cmd->add_option("--candidates", a->candidates,
                  "boundary (default: points every --spacing of arc length) or FILE.json {\"candidates\": [...]}");
  cmd->add_option("--spacing", a->spacing, "Arc length between boundary candidates (default: 24 evenly spaced)");
  cmd->add_option("--push", a->push, "Rank by the sustained (default, J) or the one-step (step, S) region")
      ->check(CLI::IsMember({"sustained", "step"}));
  cmd->add_option("--mu", a->mu, "Fixel friction M, or lo,hi (default: the scene's largest fixel mu, else 1/10)");
  cmd->add_option("--pusher-mu", a->pusher_mu, "Pusher friction M, or lo,hi judged at hi (default: the scene's)");
  cmd->add_option("--gap", a->gap, "Gap of every fixel for the one-step score (default 0)");
  cmd->add_option("--resolution", a->resolution, "Region resolution in curve parameter (default 1/256)");
  cmd->add_option("--top", a->top, "Report the K best layouts (default 5)")->transform(decimal_integer());
  cmd->add_option("--jobs", a->jobs, "Threads (default 0: one per core); the result does not depend on it")
      ->transform(decimal_integer());
  cmd->add_flag("--exhaustive", a->exhaustive,
                "Score every triple (default: in order of the pair bound, stopping when none left can enter the top K; "
                "the same layouts)");
  cmd->add_option("--svg", a->svg_path, "Draw the best three layouts and their regions to this SVG file");
  cmd->add_option("--scene-out", a->scene_out,
                  "Write the best layout as a scene file (the part with its three fixels), for region, push and seat");
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_design(*a); }};
}

}  // namespace fixel::cli
