// gfec_differential: random charts and traces, each run by the reference interpreter and by
// the C engine that gfec generates (gcc and clang, -O0 and -O2, C99 and C11, with and without
// hooks, once under ASan+UBSan); every engine must print exactly the interpreter's log. A team
// machine runs as 2 to 4 engines in lockstep under the reference exchange. A failing case is
// shrunk to a minimal chart and trace and printed with both logs.
//
//   gfec_differential [--seed N] [--cases N]     (ctest runs a few hundred; long runs:
//                                                 docs/verification.md)
//   gfec_differential --target NAME [--cases N]  each engine built for an emulated
//                                                 microcontroller and run there (docs/targets.md)
//   gfec_differential --target NAME --chart F.sfc...   hand-written charts with their traces
#include "harness.h"
#include "shrink.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <iostream>
#include <sstream>
#include <unistd.h>

using namespace gfec::diff;
namespace targets = gfec::targets;

namespace {

struct Failure {
  Case c;
  Config config;
  Outcome outcome;
};

std::string read_text(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool have(const std::string &tool) { return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0; }

/// The two logs, line by line, the first difference marked.
std::string compare(const std::string &expected, const std::string &actual) {
  std::istringstream e(expected), a(actual);
  std::string out, le, la;
  bool marked = false;
  for (int n = 1;; ++n) {
    bool ge = static_cast<bool>(std::getline(e, le)), ga = static_cast<bool>(std::getline(a, la));
    if (!ge && !ga) break;
    if (!ge) le = "<end>";
    if (!ga) la = "<end>";
    bool differ = le != la;
    out += fmt::format("{} {:4}  {:<40} {}\n", differ && !marked ? ">>" : "  ", n, le, differ ? "| " + la : "");
    marked = marked || differ;
  }
  return out;
}

void report(const Failure &f, int steps) {
  std::cout << fmt::format("\n==== case {} fails under '{}': {} (shrunk in {} tries)\n", f.c.id, f.config.name,
                           verdict_name(f.outcome.verdict), steps);
  std::cout << "---- chart\n" << f.c.text << "---- trace\n" << f.c.csv;
  if (f.outcome.verdict == Verdict::Mismatch || f.outcome.verdict == Verdict::Crash)
    std::cout << "---- interpreter (left) | engine (right)\n" << compare(f.outcome.expected, f.outcome.detail);
  else std::cout << "---- " << f.outcome.detail;
}

}  // namespace

int main(int argc, char **argv) {
  std::uint64_t seed = 1;
  int cases = 300, batch = 60, shrink_max = 3, only = -1, subcharts = 0;
  std::string work, compilers, avoid;
  bool verbose = false, keep = false, no_lint = false, limits = false, loops = false;
  std::string target_name, table_path = GFEC_TARGET_TABLE, bin = GFEC_BINARY_DIR, flags_extra, flags_without;
  std::vector<std::string> charts;
  CLI::App app{"gfec_differential - random charts: the reference interpreter against the generated C engines"};
  app.add_option("--seed", seed, "Seed of the random charts and traces (same seed, same cases)");
  app.add_option("--cases", cases, "How many random charts (a third of them fsm)");
  app.add_option("--batch", batch, "Engines compiled into one program");
  app.add_option("--compilers", compilers, "Comma-separated (default: gcc,clang, those installed)");
  app.add_option("--work", work, "Scratch folder (default: a fresh one under the temp folder)");
  app.add_option("--shrink", shrink_max, "Failures to shrink and print (the rest are only counted)");
  app.add_option("--avoid", avoid, "Do not generate what a known bug breaks: dead-code (comma-separated)");
  app.add_option(
      "--subcharts", subcharts,
      "Hierarchical programs: up to N sub-charts each (sfc and fsm, nested, the same one run by several places)");
  app.add_option("--case", only, "Run only this case (of the same seed), e.g. to shrink it again");
  app.add_flag("--no-cppcheck", no_lint, "Do not run cppcheck on the engines");
  app.add_flag("--limits", limits,
               "Values near the limits: ints past 16 bits and at INT32's ends, floats that need exact rounding, "
               "a*b+c in float (always on with --target)");
  app.add_flag("--loops", loops, "Counted for loops in actions, some left by a break (docs/language.md §10)");
  app.add_option("--target", target_name,
                 "Build each case for this emulated target (a row of the target table) and run it there");
  app.add_option("--targets", table_path, "The target table (tests/targets/targets.txt)");
  app.add_option("--bin", bin, "The build tree, for {bin} in the table's run commands");
  app.add_option("--chart", charts,
                 "With --target: run this hand-written chart, its trace beside it (X.sfc: X.csv), instead of "
                 "random ones");
  app.add_option("--flags-extra", flags_extra, "With --target: compile flags after the target's (e.g. -O2)");
  app.add_option("--flags-without", flags_without,
                 "With --target: leave this flag of the target's out (e.g. -ffp-contract=off)");
  app.add_flag("--keep", keep, "Keep the scratch folder");
  app.add_flag("-v,--verbose", verbose, "Say what happens to every case");
  CLI11_PARSE(app, argc, argv);

  std::vector<std::string> list;
  if (compilers.empty()) {
    for (const char *cc : {"gcc", "clang"})
      if (have(cc)) list.push_back(cc);
  } else {
    std::istringstream in(compilers);
    for (std::string cc; std::getline(in, cc, ',');) list.push_back(cc);
  }
  if (list.empty()) {
    std::cerr << "gfec_differential: no C compiler found\n";
    return 2;
  }
  targets::Table table;
  std::vector<Config> target_configs;
  if (!target_name.empty()) {
    table = targets::read_table(table_path);
    if (!table.error.empty()) return std::cerr << "gfec_differential: " << table.error << "\n", 2;
    const targets::Target *t = table.find(target_name);
    if (!t)
      return std::cerr << "gfec_differential: no target '" << target_name << "' (known: " << table.names() << ")\n", 2;
    // A test whose tool is missing fails in CI (scripts/install-deps.sh installs them all) and
    // is skipped elsewhere (ctest's SKIP_RETURN_CODE).
    const std::map<std::string, std::string> vars = {{"bin", bin}};
    for (const std::string &tool : {t->cc, t->emulator(vars)})
      if (!have(tool)) {
        const bool ci = std::getenv("CI") && std::string(std::getenv("CI")) == "true";
        std::cerr << fmt::format("gfec_differential: target {} needs '{}', which is not installed{}\n", t->name, tool,
                                 ci ? " (scripts/install-deps.sh)" : ": skipped");
        return ci ? 1 : 77;
      }
    Config config = target_config(*t, table.folder, bin);
    if (!flags_without.empty()) {
      std::string kept;
      std::istringstream words(config.command);
      for (std::string w; words >> w;)
        if (w != flags_without) kept += (kept.empty() ? "" : " ") + w;
      config.command = kept;
    }
    if (!flags_extra.empty()) config.command += " " + flags_extra;
    if (!flags_extra.empty() || !flags_without.empty()) config.name = t->name + ": " + config.command;
    target_configs.push_back(config);
    limits = true;
    no_lint = true;  // the host runs already lint every engine
  } else if (!charts.empty()) {
    return std::cerr << "gfec_differential: --chart runs hand-written charts on a --target\n", 2;
  }
  if (work.empty())
    work = (std::filesystem::temp_directory_path() / fmt::format("gfec-differential-{}", ::getpid())).string();
  const auto configs = target_configs.empty() ? default_configs(list) : target_configs;
  const bool lint = !no_lint && have("cppcheck");
  // Options are checked before the harness makes its scratch folder, so a refused run leaves none.
  GenOptions base;
  base.subcharts = subcharts;
  base.limits = limits;
  base.loops = loops;
  // Where double is binary32 a chart that declares one is refused (the hand cases check that):
  // the random charts use float and int there, so that they run.
  base.doubles = target_configs.empty() || target_configs[0].target->double_bits == 64;
  for (std::istringstream in(avoid); std::getline(in, avoid, ',');) {
    // Keys whose bugs are fixed are gone; a script still passing one is told so rather than
    // silently getting every construct it meant to leave out.
    if (avoid == "dead-code") base.dead_code = false;
    else if (avoid == "octal" || avoid == "float-into-int" || avoid == "call-order")
      return std::cerr << "gfec_differential: --avoid '" << avoid
                       << "' is retired: the bug it worked around is fixed, so the construct is always generated "
                          "(docs/verification.md); drop it\n",
             2;
    else return std::cerr << "gfec_differential: unknown --avoid '" << avoid << "' (known: dead-code)\n", 2;
  }
  Harness harness(work, verbose);
  const auto start = std::chrono::steady_clock::now();

  if (!charts.empty()) cases = static_cast<int>(charts.size());
  std::vector<Case> all(static_cast<std::size_t>(cases));
  std::vector<Case *> ready;
  std::vector<Failure> failures;
  int undefined = 0, invalid = 0, fsm = 0, teams = 0, generated = 0, scalable = 0, scalable_fsm = 0, hierarchical = 0;
  for (int k = 0; k < cases; ++k) {
    if (only >= 0 && k != only) continue;
    if (!charts.empty()) {  // a hand-written chart and its trace, as they are
      Case &c = all[static_cast<std::size_t>(k)];
      const std::filesystem::path chart = charts[static_cast<std::size_t>(k)];
      c.id = k;
      c.given = true;
      c.file = chart.filename().string();
      c.text = read_text(chart.string());
      auto csv = chart;
      c.csv = read_text(csv.replace_extension(".csv").string());
      // No trace: a chart without inputs runs the ticks its `// ticks: N` line says (else 1).
      if (c.csv.empty()) {
        const auto at = c.text.find("// ticks: ");
        const int ticks = at == std::string::npos ? 1 : std::atoi(c.text.c_str() + at + 10);
        c.csv = "tick\n";
        for (int t = 1; t <= ticks; ++t) c.csv += std::to_string(t) + "\n";
      }
      if (c.text.empty()) return std::cerr << "gfec_differential: cannot read " << chart.string() << "\n", 2;
      ++generated;
      Outcome o = harness.prepare(c);
      if (o.verdict == Verdict::Pass) ready.push_back(&c);
      else failures.push_back({c, {"gfec (front end)", "", false}, o});
      continue;
    }
    std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(k)};
    std::mt19937_64 rng(s);
    Case &c = all[static_cast<std::size_t>(k)];  // each case depends only on (seed, k)
    c.id = k;
    GenOptions options = base;
    options.fsm = k % 3 == 2;
    // Every other fsm is a team machine of 2 to 4 agents (docs/language.md "Teams").
    if (options.fsm && k % 6 == 5) options.agents = 2 + (k / 6) % 3;
    fsm += options.fsm;
    teams += options.agents > 0;
    ++generated;
    c.id = k;
    scalable += !options.fsm && scalable_form(c);
    scalable_fsm += options.fsm && scalable_form(c);
    c.chart = random_chart(rng, k, options);
    c.trace = random_trace(rng, c.chart, options.limits);
    // A hierarchical program: the root has a place or state that runs a sub-chart.
    hierarchical +=
        std::any_of(c.chart.places.begin(), c.chart.places.end(), [](const GPlace &p) { return p.runs >= 0; });
    Outcome o = harness.prepare(c);
    if (verbose && o.verdict != Verdict::Pass)
      std::cout << fmt::format("case {}: {}\n{}", k, verdict_name(o.verdict), o.detail);
    if (o.verdict == Verdict::Undefined) {
      ++undefined;
    } else if (o.verdict == Verdict::Invalid) {
      ++invalid;
      failures.push_back({c, {"gfec (front end)", "", false}, o});
    } else if (o.verdict != Verdict::Pass) {
      failures.push_back({c, {"gfec (back end)", "", false}, o});
    } else {
      ready.push_back(&c);
    }
  }

  int refused = 0, too_big = 0;
  for (std::size_t b = 0; b < ready.size(); b += static_cast<std::size_t>(batch)) {
    std::vector<Case *> group(
        ready.begin() + static_cast<std::ptrdiff_t>(b),
        ready.begin() + static_cast<std::ptrdiff_t>(std::min(ready.size(), b + static_cast<std::size_t>(batch))));
    if (lint) {
      auto outcomes = harness.lint_batch(group, fmt::format("b{}lint", b));
      for (std::size_t i = 0; i < group.size(); ++i)
        if (outcomes[i].verdict != Verdict::Pass)
          failures.push_back({*group[i],
                              {"cppcheck", "cppcheck --enable=warning,style,performance,portability --std=c99", false},
                              outcomes[i]});
    }
    for (std::size_t k = 0; k < configs.size(); ++k) {
      auto outcomes = harness.run_batch(group, configs[k], fmt::format("b{}c{}", b, k));
      for (std::size_t i = 0; i < group.size(); ++i) {
        refused += outcomes[i].refused;
        if (!charts.empty())
          std::cout << fmt::format("{}: {}\n", group[i]->file,
                                   outcomes[i].refused ? "refused at compile time, as it must be"
                                                       : verdict_name(outcomes[i].verdict));
        if (outcomes[i].verdict == Verdict::Pass) continue;
        if (outcomes[i].verdict == Verdict::TooBig && charts.empty()) {  // said, and run on a bigger part
          ++too_big;
          if (verbose) std::cout << fmt::format("case {} does not fit: {}", group[i]->id, outcomes[i].detail);
          continue;
        }
        failures.push_back({*group[i], configs[k], outcomes[i]});
        if (verbose)
          std::cout << fmt::format("case {} under '{}': {}\n", group[i]->id, configs[k].name,
                                   verdict_name(outcomes[i].verdict));
      }
    }
    if (verbose)
      std::cout << fmt::format("{} of {} cases run\n", std::min(ready.size(), b + static_cast<std::size_t>(batch)),
                               ready.size());
  }

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format(
      "gfec_differential: seed {}: {} random charts ({} sfc, {} of them in the scalable form, {} fsm, {} of them in "
      "the scalable form and {} team machines; {} hierarchical); {} compared under {} builds "
      "({} engine runs){}, {} skipped for undefined behaviour, {} rejected by gfec; {} failures; {:.0f} s\n",
      seed, generated, generated - fsm, scalable, fsm, scalable_fsm, teams, hierarchical, ready.size(), configs.size(),
      ready.size() * configs.size(), lint ? " and cppcheck" : "", undefined, invalid, failures.size(), seconds);
  if (!target_configs.empty())
    std::cout << fmt::format("on {}: {} compared, {} refused at compile time (a double where double is binary32), {} "
                             "too big for the part; {} failures\n",
                             target_configs[0].name, ready.size() - static_cast<std::size_t>(refused + too_big),
                             refused, too_big, failures.size());
  // Shrink the first failures (one per case: the same bug tends to fail every build).
  std::vector<int> shown;
  for (auto &f : failures) {
    if (static_cast<int>(shown.size()) >= shrink_max) break;
    if (std::find(shown.begin(), shown.end(), f.c.id) != shown.end()) continue;
    shown.push_back(f.c.id);
    int steps = 0;
    if (!f.c.given && (f.outcome.verdict == Verdict::Mismatch || f.outcome.verdict == Verdict::Crash ||
                       f.outcome.verdict == Verdict::CompileError || f.outcome.verdict == Verdict::Lint ||
                       f.outcome.verdict == Verdict::NotRefused)) {
      Outcome o = shrink(harness, f.c, f.config, f.outcome.verdict, &steps);
      if (o.verdict == f.outcome.verdict) f.outcome = o;
    }
    report(f, steps);
    std::string dir = fmt::format("{}/failure-{}", work, f.c.id);
    harness.save(f.c, f.outcome, f.config, dir);
    std::cout << "---- saved in " << dir << "\n";
    keep = true;
  }
  if (!keep) std::filesystem::remove_all(work);
  return failures.empty() ? 0 : 1;
}
