#include "validate/dem/verify_dem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <tbb/global_control.h>

#include "src/errors.h"
#include "validate/dem/cases.h"

namespace sandpic {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Why a case does not run with these options ("" : it runs).
std::string full_run_only(const VerifyOptions& opt) { return opt.quick ? "not run with --quick (the full run only)" : ""; }
std::string needs_a_model(const VerifyOptions& opt) {
  for (Layers l : opt.layer_models)
    if (l != Layers::AllDynamic) return "";
  return "not run: --layers names no model to hold against all-dynamic";
}
std::string always(const VerifyOptions&) { return ""; }

struct Case {
  std::string id;
  VerifyCase (*run)(const VerifyOptions&);
  std::string (*skipped)(const VerifyOptions&) = always;
};
const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"settling", verify::settling}, {"restitution", verify::restitution}, {"incline", verify::incline},
      {"rolling", verify::rolling},   {"notch", verify::notch},             {"heap", verify::heap},
      {"creep", verify::creep},       {"layers", verify::layers, needs_a_model}, {"step", verify::step},
      {"engines", verify::engines},   {"engine-piles", verify::engine_piles, full_run_only}};
  return all;
}

}  // namespace

bool VerifyCheck::pass() const {
  if (!std::isfinite(measured)) return false;
  switch (kind) {
    case Kind::Within: return std::abs(measured - expected) <= tolerance;
    case Kind::AtMost: return measured <= expected + tolerance;
    case Kind::AtLeast: return measured >= expected - tolerance;
  }
  return false;
}

std::string VerifyCheck::rule() const {
  const std::string u = unit.empty() ? "" : " " + unit;
  switch (kind) {
    case Kind::Within: return "within ±" + num(tolerance) + u + " of " + num(expected) + u;
    case Kind::AtMost: return "at most " + num(expected + tolerance) + u;
    case Kind::AtLeast: return "at least " + num(expected - tolerance) + u;
  }
  return "";
}

bool VerifyCase::pass() const {
  for (const VerifyCheck& c : checks)
    if (!c.pass()) return false;
  return !checks.empty();
}

bool VerifyReport::pass() const {
  for (const VerifyCase& c : cases)
    if (!c.pass()) return false;
  return !cases.empty();
}

const std::vector<std::string>& verify_case_ids() {
  static const std::vector<std::string> ids = [] {
    std::vector<std::string> v;
    for (const Case& c : cases()) v.push_back(c.id);
    return v;
  }();
  return ids;
}

namespace {

void check_case_ids(const std::vector<std::string>& only) {
  for (const std::string& id : only)
    if (std::find(verify_case_ids().begin(), verify_case_ids().end(), id) == verify_case_ids().end())
      throw InputError("--only: '" + id + "' is not a case (" + [] {
        std::string all;
        for (const std::string& i : verify_case_ids()) all += (all.empty() ? "" : ", ") + i;
        return all;
      }() + ")");
}

// A case named by --only that these options leave out would run nothing.
void check_skipped_cases(const VerifyOptions& opt) {
  for (const std::string& id : opt.only)
    for (const Case& c : cases())
      if (c.id == id && !c.skipped(opt).empty()) throw InputError("--only " + id + ": " + c.skipped(opt));
}

void check_pile_settings(const std::vector<std::string>& sets) {
  static const char* varied[] = {"mode", "seed", "physics_seed", "dem.layers", "physics.friction", "dem.rolling_resistance"};
  for (const std::string& a : sets) {
    const std::string key = a.substr(0, a.find('='));
    if (std::find(std::begin(varied), std::end(varied), key) != std::end(varied))
      throw InputError("verify-dem --set " + a + ": the pile cases vary '" + key + "' themselves");
    Scene s;
    apply_setting(s, a);  // an unknown key or a bad value: its own error
  }
}

}  // namespace

void check_verify_options(const VerifyOptions& opt) {
  check_case_ids(opt.only);
  check_skipped_cases(opt);
  check_pile_settings(opt.sets);
}

VerifyReport run_verify_dem(const VerifyOptions& opt) {
  check_verify_options(opt);
  std::unique_ptr<tbb::global_control> threads;
  if (opt.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(opt.threads));
  VerifyReport report;
  report.quick = opt.quick;
  report.sets = opt.sets;
  const auto start = std::chrono::steady_clock::now();
  for (const Case& cs : cases()) {
    const std::string& id = cs.id;
    if (!opt.only.empty() && std::find(opt.only.begin(), opt.only.end(), id) == opt.only.end()) continue;
    if (const std::string why = cs.skipped(opt); !why.empty()) {
      report.not_run.emplace_back(id, why);
      continue;
    }
    opt.log(id + ": running");
    const auto t0 = std::chrono::steady_clock::now();
    VerifyCase c = cs.run(opt);
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int failed = 0;
    for (const VerifyCheck& k : c.checks) failed += !k.pass();
    opt.log(id + ": " + (c.pass() ? "pass" : std::to_string(failed) + " of " + std::to_string(c.checks.size()) + " checks fail") +
            " (" + num(c.seconds) + " s)");
    report.cases.push_back(std::move(c));
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

ordered_json verify_json(const VerifyReport& r) {
  ordered_json not_run = ordered_json::array();
  for (const auto& [id, why] : r.not_run) not_run.push_back({{"id", id}, {"why", why}});
  ordered_json cs = ordered_json::array();
  for (const VerifyCase& c : r.cases) {
    ordered_json checks = ordered_json::array();
    for (const VerifyCheck& k : c.checks)
      checks.push_back({{"name", k.name},
                        {"measured", k.measured},
                        {"expected", k.expected},
                        {"tolerance", k.tolerance},
                        {"rule", k.rule()},
                        {"unit", k.unit},
                        {"pass", k.pass()}});
    cs.push_back({{"id", c.id},
                  {"title", c.title},
                  {"reference", c.reference},
                  {"pass", c.pass()},
                  {"seconds", c.seconds},
                  {"checks", checks},
                  {"notes", c.notes}});
  }
  return {{"quick", r.quick}, {"set", r.sets},         {"pass", r.pass()},
          {"seconds", r.seconds}, {"not_run", not_run}, {"cases", cs}};
}

}  // namespace sandpic
