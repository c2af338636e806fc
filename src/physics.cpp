// The physics check on Box2D 2.4.
// The engine is a measuring instrument: its floats never feed an exact
// decision, they only produce an outcome that we report.
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/scene_json.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "fixel/curve.h"
#include "fixel/error.h"

namespace fixel::physics {

using fixel::to_string;  // physics::to_string(Outcome) would hide it

namespace {

using P2 = std::array<double, 2>;

// The part's bounding-box diagonal maps to this many engine units, so that
// b2_linearSlop (0.005 units) is 5e-5 of the part size (the issue asks ≤ 1e-4).
constexpr double kEngineSize = 100;
constexpr double kGapFraction = 1e-4;        // seated: every gap below 1e-4 · size
constexpr std::size_t kLargeOutline = 4096;  // vertices: polled every step (as polygonize.cpp's partition switch)
constexpr double kRestFraction = 1e-4;       // at rest: speed below 1e-4 · size / h
constexpr double kSlop = b2_linearSlop;
// Fixel circles are tiny; their centre sits outside f_i by the radius plus
// 1.5 slop, so that Box2D's resting overlap (between 0 and one slop past the
// polygon skin of 2 slop) puts the TRUE polygon within ±0.5 slop of f_i.
constexpr double kFixelRadius = kSlop;
constexpr double kContactOffset = kFixelRadius + 1.5 * kSlop;

// Engine inputs are floats: a value outside float's range is bad input, not
// a silent infinity (and converting it would be undefined behaviour). The
// engine value is scale · x (engine units); the message shows the user's x.
float engine_float(double x, const std::string& field, double scale = 1) {
  const double engine = scale * x;
  if (!(std::abs(engine) < 1e30)) {
    std::ostringstream shown, why;  // 2.8e+300, not std::to_string's 300 digits
    shown << x;
    why << "is outside the engine's float range (|x| < 1e30";
    if (scale != 1) why << " after scaling by " << scale << " to engine units: " << engine;
    why << ")";
    throw InputError(field, shown.str(), why.str());
  }
  return static_cast<float>(engine);
}

// Box2D asserts on degenerate polygons: weld like b2PolygonShape::Set does,
// then keep only pieces with a safely positive area (a sliver thinner than
// float resolution changes no contact).
bool engine_safe(const std::vector<b2Vec2>& v) {
  std::vector<b2Vec2> w;
  const float weld = 0.6f * b2_linearSlop;
  for (const auto& p : v) {
    bool unique = true;
    for (const auto& q : w) unique = unique && b2DistanceSquared(p, q) >= weld * weld;
    if (unique) w.push_back(p);
  }
  if (w.size() < 3) return false;
  double area = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const auto& a = w[i];
    const auto& b = w[(i + 1) % w.size()];
    area += 0.5 * (double(a.x) * b.y - double(a.y) * b.x);
  }
  return area > 1e-3;
}

double signed_distance(const P2& p, const std::vector<P2>& poly) {
  double best = INFINITY;
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const P2& a = poly[j];
    const P2& b = poly[i];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double ex = p[0] - a[0] - t * dx, ey = p[1] - a[1] - t * dy;
    best = std::min(best, ex * ex + ey * ey);
    if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * dx / dy) inside = !inside;
  }
  return inside ? -std::sqrt(best) : std::sqrt(best);
}

struct Listener : b2ContactListener {
  std::vector<float> mu;
  std::vector<int> touching;  // pieces touching each fixel
  std::vector<ContactEvent>* events = nullptr;
  int max_events = 0;
  double t = 0;
  Pose pose;

  static int fixel_of(b2Contact* c) {
    const auto a = c->GetFixtureA()->GetUserData().pointer, b = c->GetFixtureB()->GetUserData().pointer;
    return static_cast<int>(a ? a : b) - 1;
  }
  void PreSolve(b2Contact* c, const b2Manifold*) override {
    const int i = fixel_of(c);
    if (i >= 0) c->SetFriction(mu[i]);  // exactly μ_i, not a mix of two values
    c->SetRestitution(0);
  }
  void note(b2Contact* c, bool begin) {
    const int i = fixel_of(c);
    if (i < 0) return;
    const int before = touching[i];
    touching[i] += begin ? 1 : -1;
    if ((before == 0) != (touching[i] == 0) && static_cast<int>(events->size()) < max_events)
      events->push_back({t, i, begin, pose});
  }
  void BeginContact(b2Contact* c) override { note(c, true); }
  void EndContact(b2Contact* c) override { note(c, false); }
};

// The world: part body at the centre of mass (engine origin = c at the scene
// pose), fixels as static circles. Engine lengths are s × metres.
struct Engine {
  Listener listener;  // declared first: it must outlive the world
  b2World world{b2Vec2(0, 0)};
  b2Body* part = nullptr;
  std::vector<b2Body*> fixels;
  double s = 1;
  P2 c{};
};

void build(const Scene& scene, const PartPolygon& poly, Engine& e) {
  e.s = kEngineSize / poly.size;
  e.c = {to_double(scene.body.p_AoCm_A.x), to_double(scene.body.p_AoCm_A.y)};
  e.world.SetAllowSleeping(false);
  e.world.SetContactListener(&e.listener);
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.allowSleep = false;
  bd.fixedRotation = scene.body.dof == 2;
  const VectorQ& v = scene.body.velocity;
  bd.linearVelocity.Set(engine_float(to_double(v[0]), "body.velocity", e.s),
                        engine_float(to_double(v[1]), "body.velocity", e.s));
  if (scene.body.dof == 3) bd.angularVelocity = engine_float(to_double(v[2]), "body.velocity");
  e.part = e.world.CreateBody(&bd);
  int kept = 0;
  for (const auto& piece : poly.pieces) {
    std::vector<b2Vec2> v_e;
    for (const auto& p : piece) v_e.emplace_back(float(e.s * (p[0] - e.c[0])), float(e.s * (p[1] - e.c[1])));
    // Box2D polygons have at most 8 vertices: fan a larger convex piece.
    for (std::size_t i = 1; i + 1 < v_e.size(); i += b2_maxPolygonVertices - 2) {
      std::vector<b2Vec2> chunk{v_e[0]};
      for (std::size_t j = i; j < v_e.size() && j <= i + b2_maxPolygonVertices - 2; ++j) chunk.push_back(v_e[j]);
      if (!engine_safe(chunk)) continue;
      b2PolygonShape shape;
      shape.Set(chunk.data(), static_cast<int32>(chunk.size()));
      b2FixtureDef fd;
      fd.shape = &shape;
      fd.density = 0;  // mass comes from the scene, below
      fd.friction = 1;
      fd.restitution = 0;
      e.part->CreateFixture(&fd);
      ++kept;
    }
  }
  if (kept == 0) throw SceneError("body.boundary", "polygonised outline", "has no piece the engine can use");
  // Exact scene values, rounded for the engine; Box2D's I is about the body
  // origin, which is the centre of mass here.
  b2MassData md;
  md.mass = engine_float(to_double(scene.body.mass), "body.mass");
  md.center.SetZero();
  md.I = scene.body.dof == 3 ? engine_float(to_double(scene.body.inertia), "body.inertia", e.s * e.s) : 0.0f;
  e.part->SetMassData(&md);

  e.listener.touching.assign(scene.fixels.size(), 0);
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const Fixel& f = scene.fixels[i];
    const double nx = to_double(f.n_A.x), ny = to_double(f.n_A.y);
    const double fx = to_double(f.p_AoF_A.x - f.gap * f.n_A.x), fy = to_double(f.p_AoF_A.y - f.gap * f.n_A.y);
    b2BodyDef sd;
    sd.type = b2_staticBody;
    sd.position.Set(float(e.s * (fx - e.c[0]) - kContactOffset * nx), float(e.s * (fy - e.c[1]) - kContactOffset * ny));
    b2Body* body = e.world.CreateBody(&sd);
    b2CircleShape circle;
    circle.m_radius = float(kFixelRadius);
    b2FixtureDef fd;
    fd.shape = &circle;
    const double mu = to_double(f.mu);
    fd.friction = float(mu * mu);  // √(1 · μ²) = μ; PreSolve also sets μ_i
    fd.restitution = 0;
    fd.userData.pointer = i + 1;
    body->CreateFixture(&fd);
    e.fixels.push_back(body);
    e.listener.mu.push_back(float(mu));
  }
}

std::vector<P2> fixel_points(const Scene& scene) {
  std::vector<P2> out;
  for (const auto& f : scene.fixels)
    out.push_back({to_double(f.p_AoF_A.x - f.gap * f.n_A.x), to_double(f.p_AoF_A.y - f.gap * f.n_A.y)});
  return out;
}

}  // namespace

std::string to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::kSeated:
      return "seated";
    case Outcome::kJammed:
      return "jammed";
    case Outcome::kEscaped:
      return "escaped";
    case Outcome::kTimeout:
      return "timeout";
  }
  return "timeout";
}

Wrench to_wrench(const VectorQ& w, int dof, const std::string& field) {
  if (w.size() != dof)
    throw InputError(field, std::to_string(w.size()) + " components", "but the scene has dof " + std::to_string(dof));
  // Checked as given: past double range it would show only as inf, and a
  // non-zero value below float range as 0 (then "the wrench is zero").
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    const double x = to_double(w[k]);
    const bool huge = !std::isfinite(x), tiny = w[k] != 0 && !(std::abs(x) >= 1e-30);
    if (huge || tiny) {
      const std::string text = to_string(w[k]);
      throw InputError(field + "[" + std::to_string(k) + "]", text.size() > 40 ? text.substr(0, 40) + "..." : text,
                       huge ? "is beyond double range: the engine takes floats (|x| < 1e30)"
                            : "is not zero but below the engine's float range (|x| >= 1e-30, or 0)");
    }
  }
  return {to_double(w[0]), to_double(w[1]), dof == 3 ? to_double(w[2]) : 0.0};
}

Wrench parse_wrench(const std::string& text, int dof, const std::string& field) {
  return to_wrench(parse_impulse(text, dof, field), dof, field);
}

PushResult push(const Scene& scene, const VectorQ& w, const PushOptions& options) {
  return push(scene, to_wrench(w, scene.body.dof), options);
}

namespace {

// The push's own time scale (display, never a decision): the time a
// constant force takes to move the part by its size from rest, a constant
// moment to turn it by a radian, an impulse's velocity to carry it its
// size; the least of those that apply.
double push_time_scale(const Scene& scene, const Wrench& w, const PushOptions& options, double size) {
  const double m = to_double(scene.body.mass);
  double t = INFINITY;
  const double force = std::hypot(w.fx, w.fy);
  if (force > 0) t = std::min(t, std::sqrt(m * size / force));
  if (scene.body.dof == 3 && w.m != 0) t = std::min(t, std::sqrt(to_double(scene.body.inertia) / std::abs(w.m)));
  if (options.impulse) {
    const auto& p = *options.impulse;
    const double dv = std::hypot(p[0], p[1]) / m;
    if (dv > 0) t = std::min(t, size / dv);
  }
  return std::isfinite(t) ? t : 0;
}

// The thresholds are tied to h and dt (docs/physics.md, "Outcomes"); a push
// far faster or slower than them is measured badly, and says so.
void add_time_scale_warnings(PushResult& r, double h) {
  if (r.time_scale <= 0) return;
  std::ostringstream w;
  w << std::setprecision(3);
  if (r.time_scale < 50 * r.dt) {
    w << "the push's time scale, about " << r.time_scale << " s, is only " << r.time_scale / r.dt
      << " engine steps (dt = " << r.dt
      << " s): the engine may not resolve it (a timeout, or the part pushed through a fixel). "
         "Give the scene a smaller time_step h (dt = h/1000)";
    r.warnings.push_back(w.str());
  } else if (r.time_scale > 10 * h) {
    w << "the push's time scale, about " << r.time_scale << " s, is over 10 h (h = " << h
      << " s): \"at rest\" (slower than " << r.rest_speed
      << " m/s) can hold while the part still moves into its seat, so \"jammed\" may be a slow seat and "
         "\"timeout\" a seat not yet reached. Give the scene a time_step h near "
      << r.time_scale << " s";
    r.warnings.push_back(w.str());
  }
}

}  // namespace

void check_push_options(const PushOptions& options) {
  if (options.time <= 0) throw InputError("PushOptions.time", to_string(options.time), "must be > 0");
  if (options.steps_per_h < 1000)
    throw InputError("PushOptions.steps_per_h", std::to_string(options.steps_per_h), "must be >= 1000 (dt <= h/1000)");
  for (const auto& [iterations, field] : {std::pair{options.velocity_iterations, "PushOptions.velocity_iterations"},
                                          std::pair{options.position_iterations, "PushOptions.position_iterations"}})
    if (iterations < 1 || iterations > kMaxSolverIterations)
      throw InputError(field, std::to_string(iterations), "must be 1 to " + std::to_string(kMaxSolverIterations));
  // Also keeps the step count a long. Named by the steps per h when those
  // were changed from the default (they made the count too large), else by T.
  const Rational total_q = options.time * options.steps_per_h;
  if (total_q > kMaxPushSteps) {
    const std::string why = "holds the push for " + to_string(total_q) + " engine steps (time · " +
                            std::to_string(options.steps_per_h) + " per h); at most " + std::to_string(kMaxPushSteps);
    if (options.steps_per_h != PushOptions{}.steps_per_h)
      throw InputError("PushOptions.steps_per_h", std::to_string(options.steps_per_h),
                       "with time " + to_string(options.time) + " " + why);
    throw InputError("PushOptions.time", to_string(options.time), why);
  }
}

PushResult push(const Scene& scene, const Wrench& w, const PushOptions& options) {
  check_push_options(options);
  if (options.impulse)
    for (const double p : *options.impulse) engine_float(p, "PushOptions.impulse");
  if (!std::isfinite(w.fx) || !std::isfinite(w.fy) || !std::isfinite(w.m)) {
    std::ostringstream shown;
    shown << "(" << w.fx << ", " << w.fy << ", " << w.m << ")";
    throw InputError("push(wrench)", shown.str(), "has a component that is not finite");
  }
  check_scene_values(scene);  // a scene built in code: a SceneError, not a crash
  // Positive exact values that round to (near) zero in the engine's floats
  // would run with dt = 0 or an infinite acceleration.
  for (const auto& [value, field] : {std::pair{&scene.time_step, "time_step"}, std::pair{&scene.body.mass, "body.mass"},
                                     std::pair{&scene.body.inertia, "body.inertia"}}) {
    if (field == std::string("body.inertia") && scene.body.dof != 3) continue;
    if (!(to_double(*value) >= 1e-30)) {
      const std::string text = to_string(*value);
      throw InputError(field, text.size() > 40 ? text.substr(0, 40) + "..." : text,
                       "is too small for the engine's floats (at least 1e-30)");
    }
  }
  const PartPolygon poly = part_polygon(scene, options.control);
  Engine e;
  PushResult r;
  e.listener.events = &r.events;
  e.listener.max_events = options.max_events;
  build(scene, poly, e);
  if (options.impulse) {
    const auto& p = *options.impulse;
    const double mass = to_double(scene.body.mass);
    const char* field = "PushOptions.impulse";  // checked above; its velocity change must fit a float too
    e.part->SetLinearVelocity(e.part->GetLinearVelocity() +
                              b2Vec2(engine_float(e.s * p[0] / mass, field), engine_float(e.s * p[1] / mass, field)));
    if (scene.body.dof == 3)
      e.part->SetAngularVelocity(e.part->GetAngularVelocity() +
                                 engine_float(p[2] / to_double(scene.body.inertia), field));
  }

  const double h = to_double(scene.time_step);
  const int nf = scene.num_contacts();
  r.dt = h / double(options.steps_per_h);
  r.steps_per_h = options.steps_per_h;
  r.velocity_iterations = options.velocity_iterations;
  r.position_iterations = options.position_iterations;
  r.length_scale = e.s;
  r.part_size = poly.size;
  r.gap_tolerance = kGapFraction * poly.size;
  r.rest_speed = kRestFraction * poly.size / h;
  r.time_scale = push_time_scale(scene, w, options, poly.size);
  add_time_scale_warnings(r, h);
  if (nf == 0)
    r.warnings.push_back("the scene has no fixels: nothing can seat the part (the outcome cannot be seated)");
  bool moving = false;
  for (Eigen::Index k = 0; k < scene.body.velocity.size(); ++k) moving = moving || scene.body.velocity[k] != 0;
  if (w.fx == 0 && w.fy == 0 && w.m == 0 && !options.impulse && !moving)
    r.warnings.push_back("the wrench is zero and the part at rest: nothing moves it (the outcome is a timeout)");
  const Rational total_q = options.time * options.steps_per_h;  // at most kMaxPushSteps: check_push_options
  const long total = static_cast<long>(std::ceil(to_double(total_q)));
  const long sample_every = std::max<long>(1, total / std::max(1, options.trajectory_samples));

  // The outline about the centre of mass, its radius, and the fixel points.
  std::vector<P2> local;
  double radius = 0;
  for (const auto& p : poly.outline) {
    local.push_back({p[0] - e.c[0], p[1] - e.c[1]});
    radius = std::max(radius, std::hypot(local.back()[0], local.back()[1]));
  }
  const std::vector<P2> f = fixel_points(scene);
  const double m = to_double(scene.body.mass);
  const P2 accel{w.fx / m, w.fy / m};
  const b2Vec2 force(engine_float(w.fx, "push(wrench)", e.s), engine_float(w.fy, "push(wrench)", e.s));
  const float torque = scene.body.dof == 3 ? engine_float(w.m, "push(wrench)", e.s * e.s) : 0.0f;

  std::vector<double> gaps(nf);
  auto measure = [&](Pose& pose, bool with_gaps) {
    const b2Vec2 x = e.part->GetPosition();
    pose = {x.x / e.s, x.y / e.s, e.part->GetAngle()};
    if (!with_gaps) return;
    const double cs = std::cos(pose.theta), sn = std::sin(pose.theta);
    for (int i = 0; i < nf; ++i) {
      const double dx = f[i][0] - e.c[0] - pose.x, dy = f[i][1] - e.c[1] - pose.y;
      gaps[i] = signed_distance({cs * dx + sn * dy, -sn * dx + cs * dy}, local);
    }
  };
  Pose pose;
  measure(pose, true);
  r.trajectory.push_back({0, pose});
  long seat_run = 0, jam_run = 0;
  // Every 1024 steps; every step for a large outline, whose steps take
  // milliseconds each (thousands of convex pieces).
  const long poll_every = poly.outline.size() >= kLargeOutline ? 1 : 1024;
  for (long step = 1; step <= total; ++step) {
    if ((step - 1) % poll_every == 0) poll(options.control, "push", step - 1, total, "engine steps");
    e.listener.t = double(step) * r.dt;
    e.listener.pose = pose;
    e.part->ApplyForceToCenter(force, true);
    e.part->ApplyTorque(torque, true);
    e.world.Step(float(r.dt), options.velocity_iterations, options.position_iterations);
    r.steps = step;
    const double t = double(step) * r.dt;
    const b2Vec2 v_e = e.part->GetLinearVelocity();
    const P2 v{v_e.x / e.s, v_e.y / e.s};
    const double speed = std::hypot(v[0], v[1]) + std::abs(e.part->GetAngularVelocity()) * radius;
    const bool at_rest = speed < r.rest_speed;
    // Gaps only matter at rest (and at the end): skip them while moving.
    measure(pose, at_rest || step == total);
    bool closed = true, touching = false;
    for (int i = 0; i < nf; ++i) {
      closed = closed && gaps[i] < r.gap_tolerance;
      touching = touching || e.listener.touching[i] > 0;
    }
    seat_run = at_rest && closed ? seat_run + 1 : 0;
    jam_run = at_rest && touching && !closed ? jam_run + 1 : 0;
    if (seat_run == 1) r.time_to_seat = t;
    if (seat_run == 0) r.time_to_seat.reset();
    // Escape is proved for free flight: the part stays within `radius` of its
    // centre of mass, and each fixel's distance to that centre only grows
    // when position, velocity and acceleration all point away from it.
    bool escaped = !touching;
    const P2 com{e.c[0] + pose.x, e.c[1] + pose.y};
    for (int i = 0; i < nf && escaped; ++i) {
      const P2 d{com[0] - f[i][0], com[1] - f[i][1]};
      escaped = std::hypot(d[0], d[1]) > radius + 2 * r.gap_tolerance && d[0] * v[0] + d[1] * v[1] > 0 &&
                d[0] * accel[0] + d[1] * accel[1] >= 0 && v[0] * accel[0] + v[1] * accel[1] >= 0;
    }
    if (step % sample_every == 0) r.trajectory.push_back({t, pose});
    if (seat_run >= options.steps_per_h) r.outcome = Outcome::kSeated;
    if (jam_run >= options.steps_per_h) r.outcome = Outcome::kJammed;
    if (escaped && nf > 0) r.outcome = Outcome::kEscaped;
    if (r.outcome != Outcome::kTimeout && options.stop_at_outcome) break;
  }
  if (r.outcome != Outcome::kSeated) r.time_to_seat.reset();
  measure(pose, true);
  r.time_end = double(r.steps) * r.dt;
  r.final_pose = pose;
  r.final_gaps = gaps;
  if (r.trajectory.back().t != r.time_end) r.trajectory.push_back({r.time_end, pose});
  for (int i = 0; i < nf; ++i) {
    if (e.listener.touching[i] > 0) r.contacts_at_rest.push_back(i);
    if (r.outcome == Outcome::kJammed && gaps[i] >= r.gap_tolerance) r.open_fixels.push_back(i);
  }
  return r;
}

std::vector<double> initial_engine_gaps(const Scene& scene) {
  const PartPolygon poly = part_polygon(scene);
  Engine e;
  std::vector<ContactEvent> events;
  e.listener.events = &events;
  build(scene, poly, e);
  std::vector<double> out;
  for (std::size_t i = 0; i < e.fixels.size(); ++i) {
    const b2Vec2 q = e.fixels[i]->GetPosition();
    // Distance from the circle's centre to the union of the engine's pieces.
    double best = INFINITY;
    for (b2Fixture* fx = e.part->GetFixtureList(); fx; fx = fx->GetNext()) {
      const auto* shape = static_cast<const b2PolygonShape*>(fx->GetShape());
      std::vector<P2> piece;
      for (int k = 0; k < shape->m_count; ++k) {
        const b2Vec2 p = e.part->GetWorldPoint(shape->m_vertices[k]);
        piece.push_back({p.x, p.y});
      }
      best = std::min(best, std::max(0.0, signed_distance({q.x, q.y}, piece)));
    }
    out.push_back((best - kContactOffset) / e.s);
  }
  return out;
}

}  // namespace fixel::physics
