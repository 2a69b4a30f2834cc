#include "paths.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "io.h"
#include "rng.h"

namespace bvb {

Pose step_pose(const Pose &p, double forward_in, double turn_deg) {
  const double h0 = deg2rad(p.heading_deg), dth = deg2rad(turn_deg);
  Pose q = p;
  q.heading_deg = p.heading_deg + turn_deg;
  if (std::fabs(dth) < 1e-12) {
    q.x_in += forward_in * std::cos(h0);
    q.y_in += forward_in * std::sin(h0);
  } else {
    // Chord of the arc: length 2 R sin(dth / 2) in the direction h0 + dth / 2.
    const double chord = forward_in * std::sin(dth * 0.5) / (dth * 0.5);
    q.x_in += chord * std::cos(h0 + dth * 0.5);
    q.y_in += chord * std::sin(h0 + dth * 0.5);
  }
  return q;
}

namespace {
// A path longer than this is a mistake: at 16 bytes a step, the cap bounds a script's memory.
constexpr double kMaxSteps = 1e6;
}  // namespace

std::vector<Step> expand_script(const std::string &script, double speed_in, double turn_rate_deg) {
  if (!(speed_in > 0) || !(turn_rate_deg > 0))
    throw InputError("path: speed and turn rate must be > 0");
  std::vector<Step> steps;
  size_t pos = 0;
  if (script.empty()) throw InputError("path: empty script");
  while (pos <= script.size()) {
    size_t end = script.find('+', pos);
    if (end == std::string::npos) end = script.size();
    const std::string tok = script.substr(pos, end - pos);
    if (tok.size() < 2 || !std::strchr("FBLRS", tok[0]))
      throw InputError("path '" + script + "': bad move '" + tok +
                       "' (expected F<in>, B<in>, L<deg>, R<deg> or S<frames> joined by '+')");
    const std::string num = tok.substr(1);
    errno = 0;
    char *e = nullptr;
    const double v = std::strtod(num.c_str(), &e);
    if (*e != '\0' || errno == ERANGE || !std::isfinite(v) || v < 0 || v > 1e6 ||
        num.find_first_not_of("0123456789.") != std::string::npos)
      throw InputError("path '" + script + "': bad amount in '" + tok + "'");
    const char kind = tok[0];
    if (kind == 'S') {
      if (v != std::floor(v)) throw InputError("path '" + script + "': S takes whole frames");
      // Checked before the pauses are added: each S is within the cap, many of them are not.
      if (v + double(steps.size()) > kMaxSteps)
        throw InputError("path '" + script.substr(0, 40) + (script.size() > 40 ? "...'" : "'") +
                         ": more than a million steps");
      for (int k = 0; k < int(v); ++k) steps.push_back({0, 0});
    } else {
      const bool turn = kind == 'L' || kind == 'R';
      const double rate = turn ? turn_rate_deg : speed_in;
      const double sign = (kind == 'B' || kind == 'R') ? -1 : 1;
      const long full = long(std::floor(v / rate + 1e-9));
      double rest = v - double(full) * rate;
      if (rest < 1e-9 * rate) rest = 0;
      if (double(full) + double(steps.size()) > kMaxSteps)
        throw InputError("path '" + script.substr(0, 40) + (script.size() > 40 ? "...'" : "'") +
                         ": more than a million steps");
      for (long k = 0; k <= full; ++k) {
        const double amount = k < full ? rate : rest;
        if (amount <= 0) continue;
        steps.push_back(turn ? Step{0, sign * amount} : Step{sign * amount, 0});
      }
    }
    pos = end + 1;
  }
  return steps;
}

namespace {
std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
}  // namespace

std::string path_script(const std::string &name, double length_in, double angle_deg,
                        double side_in, bool square_left) {
  if (name == "straight") return (length_in < 0 ? "B" : "F") + num(std::fabs(length_in));
  if (name == "turn") return (angle_deg < 0 ? "R" : "L") + num(std::fabs(angle_deg));
  if (name == "square") {
    const std::string leg = "F" + num(side_in) + (square_left ? "+L90" : "+R90");
    return leg + "+" + leg + "+" + leg + "+" + leg;
  }
  if (name == "odo_a") return "F36+R90+F11";
  if (name == "odo_b") return "F36+L90+F9.5";
  if (!name.empty() && std::strchr("FBLRS", name[0])) {
    expand_script(name, 1, 1);  // validates
    return name;
  }
  throw InputError("path '" + name +
                   "': unknown (expected straight, turn, square, odo_a, odo_b, avoid or a script "
                   "like F36+R90+F11)");
}

int64_t Encoders::left_ticks() const { return int64_t(std::floor(left_count + 0.5)); }
int64_t Encoders::right_ticks() const { return int64_t(std::floor(right_count + 0.5)); }

void encoders_step(Encoders &e, const EncoderModel &m, const Step &step, uint64_t seed) {
  const double half = deg2rad(step.turn_deg) * m.wheelbase_in * 0.5;
  const double travel[2] = {step.forward_in - half, step.forward_in + half};
  double *count[2] = {&e.left_count, &e.right_count};
  for (int w = 0; w < 2; ++w) {
    SceneRng rng(hash_key(seed, uint64_t(w)));
    const double g1 = rng.gaussian(), g2 = rng.gaussian();
    double c = travel[w] * m.ticks_per_inch;
    if (m.slip > 0) c *= 1 + m.slip * std::fabs(g1);
    if (m.noise_ticks > 0) c += m.noise_ticks * g2;
    *count[w] += c;
  }
}

Pose odometry_step(const Pose &p, int64_t dleft_ticks, int64_t dright_ticks, const EncoderModel &m) {
  const double dl = double(dleft_ticks) / m.ticks_per_inch, dr = double(dright_ticks) / m.ticks_per_inch;
  return step_pose(p, 0.5 * (dl + dr), rad2deg((dr - dl) / m.wheelbase_in));
}

}  // namespace bvb
