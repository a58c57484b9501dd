// The ALICA front end (docs/alica.md): the JSON reader keeps positions and exact ids; plans
// become the same syntax tree chart text would; every diagnostic points into the .pml file at
// the element it is about, with its name and id. Fixtures: tests/alica/ (written for gfec in
// ALICA's format).
#include "support.h"

#include "alica/identifiers.h"
#include "alica/json_tree.h"
#include "input_languages.h"
#include "dot_chart.h"
#include "json_backend.h"
#include "validate.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

using namespace gfec;
namespace fs = std::filesystem;

namespace {

const fs::path kFixtures = fs::path(GFEC_SOURCE_DIR) / "tests" / "alica";

/// Every fixture file, by its path relative to tests/alica (as the in-memory loader sees it).
std::map<std::string, std::string> fixture_files() {
  std::map<std::string, std::string> files;
  for (const auto &e : fs::recursive_directory_iterator(kFixtures))
    if (e.is_regular_file())
      files[fs::relative(e.path(), kFixtures).generic_string()] = test::read_file(e.path().string());
  return files;
}

/// The front end and the validator over the fixtures (plus `extra`), from `main`.
struct Run : test::Pipeline {
  std::string text;

  explicit Run(const std::string &main, const std::map<std::string, std::string> &extra = {})
      : Pipeline(main, files(extra)), text(Pipeline::text()) {}
  static MemoryFileSystem files(const std::map<std::string, std::string> &extra) {
    MemoryFileSystem mem;
    for (const auto &[path, t] : fixture_files()) mem.add(path, t);
    for (const auto &[path, t] : extra) mem.add(path, t);
    return mem;
  }
  const model::Chart *chart(const std::string &name) const {
    for (const auto &c : model.charts)
      if (c.name == name) return &c;
    return nullptr;
  }
};

/// "LINE:COL" of the '{' that opens the JSON object whose "id" is `id`, in fixture `file`.
std::string object_at(const std::string &file, const std::string &id) {
  std::string text = test::read_file((kFixtures / file).string());
  std::size_t at = text.find("\"id\" : " + id + ",");
  REQUIRE(at != std::string::npos);
  std::size_t brace = text.rfind('{', at);
  std::size_t line =
      1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(brace), '\n'));
  std::size_t col = brace - (text.rfind('\n', brace) + 1) + 1;
  return fmt::format("{}:{}", line, col);
}

std::vector<std::string> place_names(const model::Chart &c) {
  std::vector<std::string> names;
  for (const auto &p : c.places) names.push_back(p.name.str());
  return names;
}

}  // namespace

TEST_CASE("alica json: values keep their positions and ids their exact digits", "[alica]") {
  std::string text =
      "{\n  \"id\" : 4611686018427387905,\n  \"name\" : \"A\\u00e9\\n\",\n  \"x\" : [ 1.5e3, true, null ]\n}";
  alica::JsonError error;
  auto v = alica::parse_json(text, error);
  REQUIRE(v);
  REQUIRE(v->is_object());
  const alica::JsonValue *id = v->find("id");
  REQUIRE(id);
  // 4611686018427387905 is 2^62 + 1: a double would have rounded it to 2^62.
  CHECK(id->as_id() == std::optional<std::string>("4611686018427387905"));
  CHECK(text.substr(id->begin, id->end - id->begin) == "4611686018427387905");
  CHECK(v->string_of("name") == "A\xc3\xa9\n");
  const alica::JsonValue *x = v->find("x");
  REQUIRE(x);
  REQUIRE(x->items.size() == 3);
  CHECK(x->items[0].text == "1.5e3");
  CHECK(!x->items[0].as_id());
  CHECK(x->items[1].boolean);
  CHECK(x->items[2].is_null());
  CHECK(v->begin == 0);
  CHECK(v->end == text.size());
}

TEST_CASE("alica json: malformed text is refused with the offset of the first fault", "[alica]") {
  struct Case {
    std::string text;
    std::uint32_t offset;
    std::string message;
  } cases[] = {
      {"{ \"a\" : 1 \"b\" : 2 }", 10, "expected ',' or '}' in an object, found '\"'"},
      {"[ 1, 2", 6, "expected ',' or ']' in an array, found the end of the file"},
      {"{ \"a\" : tru }", 8, "expected a JSON value, found 't'"},
      {"\"abc", 4, "unterminated string: the file ends inside it"},
      {"{ \"a\" : 1 } x", 12, "unexpected text after the JSON document"},
      {"{ a : 1 }", 2, "expected a member name in quotes, found 'a'"},
      {"", 0, "expected a JSON value, found the end of the file"},
  };
  for (const auto &c : cases) {
    INFO(c.text);
    alica::JsonError error;
    CHECK(!alica::parse_json(c.text, error));
    CHECK(error.offset == c.offset);
    CHECK(error.message == c.message);
  }
  // Deep nesting is refused, not a stack overflow.
  alica::JsonError error;
  CHECK(!alica::parse_json(std::string(100000, '['), error));
  CHECK(error.message == "JSON nested more than 256 deep");
}

TEST_CASE("alica: a plan with one entry point becomes an fsm with its states and transitions", "[alica]") {
  Run r("plans/Master.pml");
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *m = r.chart("Master");
  REQUIRE(m);
  CHECK(m->kind == model::Chart::Kind::Fsm);
  CHECK(m->in_main_file);
  // "Fetch Item" is no identifier: the space becomes '_'.
  CHECK(place_names(*m) == std::vector<std::string>{"Search", "Fetch_Item", "Retry", "Done"});
  CHECK(m->places[0].initial);
  CHECK(m->places[3].terminal == model::Terminal::Success);
  REQUIRE(m->transitions.size() == 4);
  CHECK(m->transitions[0].name == "Found");
  CHECK(m->transitions[0].inputs == test::ids<model::PlaceId>({0}));
  CHECK(m->transitions[0].outputs == test::ids<model::PlaceId>({1}));
  // Behaviours are action functions, preconditions sensing functions; an unnamed precondition
  // is named after its transition.
  std::vector<std::string> functions;
  for (model::FunctionId f : m->functions)
    functions.push_back(fmt::format("{} {}", model::type_name(r.model.functions[f].result), r.model.functions[f].name));
  CHECK(functions == std::vector<std::string>{"void SearchItem", "void Park", "bool ItemSeen", "bool Parked"});
  // ALICA's standard conditions on the child plan read the sub-chart's outcome.
  REQUIRE(m->transitions[1].condition);
  CHECK(m->transitions[1].condition->kind == model::Expr::Kind::Succeeded);
  CHECK(m->transitions[1].condition->place() == model::PlaceId(1));
  REQUIRE(m->transitions[2].condition);
  CHECK(m->transitions[2].condition->kind == model::Expr::Kind::Failed);
  // The state holding Fetch.pml runs Fetch's machine (a sub-chart), read from its own file.
  CHECK(m->places[1].runs.valid());
  CHECK(r.model.charts.at(m->places[1].runs).name == "Fetch");
  const model::Chart *fetch = r.chart("Fetch");
  REQUIRE(fetch);
  CHECK(!fetch->in_main_file);
  CHECK(place_names(*fetch) == std::vector<std::string>{"Go", "Grab", "Got", "Lost"});
  CHECK(fetch->places[3].terminal == model::Terminal::Failure);
  // -MD lists every file read: the plans, behaviours and the task repository.
  CHECK(std::find(r.loaded.paths.begin(), r.loaded.paths.end(), "tasks/TaskRepository.tsk") != r.loaded.paths.end());
  CHECK(std::find(r.loaded.paths.begin(), r.loaded.paths.end(), "plans/Fetch.pml") != r.loaded.paths.end());
  CHECK(std::find(r.loaded.paths.begin(), r.loaded.paths.end(), "plans/Behaviours/DriveToItem.beh") !=
        r.loaded.paths.end());
}

TEST_CASE("alica: a plan with several entry points becomes an sfc whose initial places run one machine each",
          "[alica]") {
  Run r("plans/Team.pml");
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *team = r.chart("Team");
  REQUIRE(team);
  CHECK(team->kind == model::Chart::Kind::Sfc);
  // Entry points are named after their task when they have no name of their own.
  CHECK(place_names(*team) == std::vector<std::string>{"Leader", "Helper"});
  CHECK(team->places[0].initial);
  CHECK(team->places[1].initial);
  REQUIRE(team->places[0].runs.valid());
  CHECK(r.model.charts.at(team->places[0].runs).name == "TeamLeader");
  REQUIRE(team->places[1].runs.valid());
  CHECK(r.model.charts.at(team->places[1].runs).name == "TeamHelper");
  const model::Chart *leader = r.chart("TeamLeader");
  const model::Chart *helper = r.chart("TeamHelper");
  REQUIRE(leader);
  REQUIRE(helper);
  CHECK(place_names(*leader) == std::vector<std::string>{"Lead", "Arrive"});
  CHECK(place_names(*helper) == std::vector<std::string>{"Guard", "Relieved"});
  // Behaviours in state order, then conditions in transition order; a precondition with no
  // name on a transition with none is named after its id.
  std::vector<std::string> functions;
  for (const auto &f : r.model.functions) functions.push_back(f.name);
  CHECK(functions == std::vector<std::string>{"DriveToItem", "Park", "Watch", "Arrived", "Condition1600000000031"});
}

TEST_CASE("alica: each fsm rule broken in a plan is reported at the JSON object, with names and ids", "[alica]") {
  struct Case {
    const char *plan;
    const char *id;  ///< the offending object
    const char *message;
    const char *element;
  } cases[] = {
      {"SelfLoop", "1800000000020", "error: transition from state 'Spin' to itself [self-transition]",
       "note: this is ALICA transition 'Again' (id 1800000000020) of plan 'SelfLoop' (id 1800000000000)"},
      {"SecondPair", "1800000000021", "error: second transition from 'A' to 'B' [duplicate-transition]",
       "note: this is ALICA transition 'Second' (id 1800000000021) of plan 'SecondPair' (id 1800000000000)"},
      {"LeavesTerminal", "1800000000021", "error: transition leaves terminal state 'Finished' [terminal-state]",
       "note: this is ALICA transition 'Restart' (id 1800000000021) of plan 'LeavesTerminal' (id 1800000000000)"},
      {"Disconnected", "1800000000004",
       "error: state 'Island' is not connected to the initial state 'Start' [not-connected]",
       "note: this is ALICA state 'Island' (id 1800000000004) of plan 'Disconnected' (id 1800000000000)"},
      {"TerminalBody", "1800000000103", "error: terminal state 'Parked' cannot have a body [terminal-state]",
       "note: this is ALICA state 'Parked' (id 1800000000103) of plan 'TerminalBody' (id 1800000000100)"},
  };
  for (const auto &c : cases) {
    std::string file = fmt::format("plans/broken/{}.pml", c.plan);
    Run r(file);
    INFO(r.text);
    std::string at = fmt::format("{}:{}: ", file, object_at(file, c.id));
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find(at + c.message) != std::string::npos);
    CHECK(r.text.find(at + c.element) != std::string::npos);
  }
}

TEST_CASE("alica: a plan's machine needs exactly one initial state: no entry point, or two on one state, is an error",
          "[alica]") {
  SECTION("no entry point") {
    const std::string file = "plans/broken/NoEntryPoint.pml";
    Run r(file);
    INFO(r.text);
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find(file + ":1:1: error: plan 'NoEntryPoint' (id 1800000000200) has no entry point: gfec needs one "
                             "to know where its machine starts [alica-format]") != std::string::npos);
  }
  SECTION("two entry points that start in one state") {
    const std::string file = "plans/broken/SharedEntry.pml";
    Run r(file);
    INFO(r.text);
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find(fmt::format("{}:{}: error: entry point 'Right' (id 1800000000304) starts in state 'Both', which "
                                  "entry point 'Left' (id 1800000000301) already reaches",
                                  file, object_at(file, "1800000000304"))) != std::string::npos);
    CHECK(r.text.find(fmt::format("{}:{}: note: the state is here", file, object_at(file, "1800000000302"))) !=
          std::string::npos);
  }
}

TEST_CASE("alica: dangling references are errors at the reference, with did-you-mean", "[alica]") {
  SECTION("a file that is not there") {
    Run r("plans/broken/MissingFile.pml");
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("plans/broken/MissingFile.pml:37:28: error: cannot find 'Behaviours/SerchItem.beh', referenced "
                      "here [alica-reference]") != std::string::npos);
    CHECK(r.text.find("note: did you mean 'Behaviours/SearchItem.beh'?") != std::string::npos);
    CHECK(r.text.find("note: looked for 'plans/broken/Behaviours/SerchItem.beh'") != std::string::npos);
  }
  SECTION("a file referenced twice is reported once") {
    // A second state running the same missing behaviour: one problem, one error.
    std::string text = test::read_file((kFixtures / "plans/broken/MissingFile.pml").string());
    const std::string state_start = "    {\n      \"type\" : \"State\"";
    std::size_t from = text.find(state_start), to = text.find("\n  ],\n  \"transitions\"");
    REQUIRE(from != std::string::npos);
    REQUIRE(to != std::string::npos);
    std::string second = text.substr(from, to - from);
    for (auto [a, b] : {std::pair<std::string, std::string>{"1800000000002", "1800000000003"},
                        {"1800000001002", "1800000001003"},
                        {"\"Start\"", "\"Again\""}})
      for (std::size_t at; (at = second.find(a)) != std::string::npos;) second.replace(at, a.size(), b);
    text.insert(to, ",\n" + second);
    Run r("plans/broken/Twice.pml", {{"plans/broken/Twice.pml", text}});
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("cannot find 'Behaviours/SerchItem.beh'") != std::string::npos);
    CHECK(r.text.find("cannot find 'Behaviours/SerchItem.beh'") ==
          r.text.rfind("cannot find 'Behaviours/SerchItem.beh'"));
  }
  SECTION("a task that cannot be found is a warning: it names only the entry point") {
    std::string text = test::read_file((kFixtures / "plans/broken/MissingFile.pml").string());
    for (auto [a, b] : {std::pair<std::string, std::string>{"TaskRepository.tsk#9007199254740995", "Nowhere.tsk#5"},
                        {"Behaviours/SerchItem.beh", "Behaviours/SearchItem.beh"}})
      text.replace(text.find(a), a.size(), b);
    Run r("plans/broken/NoTask.pml", {{"plans/broken/NoTask.pml", text}});
    CHECK(r.diag.error_count() == 0);
    CHECK(r.diag.warning_count() >= 1);
    CHECK(r.text.find("warning: cannot find 'Nowhere.tsk', referenced here: the entry point is labelled without its "
                      "task's name [-Walica-ignored]") != std::string::npos);
    CHECK(r.chart("MissingFile") != nullptr);
  }
  SECTION("an id the file does not hold") {
    Run r("plans/broken/MissingId.pml");
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("plans/broken/MissingId.pml:37:28: error: 'plans/Behaviours/Park.beh' has no element with id "
                      "1700000000099 [alica-reference]") != std::string::npos);
    CHECK(r.text.find("plans/Behaviours/Park.beh:1:1: note: did you mean 'Park' (id 1700000000003), which the file "
                      "holds?") != std::string::npos);
  }
  SECTION("a transition to a state the plan does not have") {
    Run r("plans/broken/MissingState.pml");
    CHECK(r.diag.error_count() == 1);
    std::string file = "plans/broken/MissingState.pml";
    CHECK(r.text.find(fmt::format("{}:{}: error: transition 'Nowhere' (id 1800000000020) of plan 'MissingState' "
                                  "(id 1800000000000) names outState 1800000000009, which the plan has no state for",
                                  file, object_at(file, "1800000000020"))) != std::string::npos);
  }
}

TEST_CASE("alica: malformed JSON and XML plans are located errors", "[alica]") {
  Run r("plans/broken/Malformed.pml");
  CHECK(r.diag.error_count() == 1);
  CHECK(r.text.find("plans/broken/Malformed.pml:8:3: error: malformed JSON: expected ',' or ']' in an array, found "
                    "'\"' [json]") != std::string::npos);
  Run xml("old.pml", {{"old.pml", "<?xml version=\"1.0\" encoding=\"ASCII\"?>\n<alica:Plan id=\"1\"/>\n"}});
  CHECK(xml.diag.error_count() == 1);
  CHECK(xml.text.find("old.pml:1:1: error: this is an XML file of ALICA's older Eclipse designer") !=
        std::string::npos);
  // -x alica on a file that is JSON but no plan.
  SourceManager sources;
  Diagnostics diag;
  MemoryFileSystem mem;
  mem.add("tasks.json", test::read_file((kFixtures / "tasks/TaskRepository.tsk").string()));
  LoadOptions options;
  options.language = find_input_language("alica");
  load_program("tasks.json", options, mem, sources, diag);
  REQUIRE(diag.error_count() == 1);
  CHECK(
      render_text(diag.all().front(), sources)
          .rfind(
              "tasks.json:1:1: error: 'tasks.json' is not an ALICA plan: a plan is a JSON object with \"entryPoints\" "
              "and \"states\" [alica-format]",
              0) == 0);
}

TEST_CASE("alica: what has no gfec counterpart is a located warning naming it", "[alica]") {
  Run r("plans/broken/Ignored.pml");
  INFO(r.text);
  CHECK(!r.diag.has_errors());
  CHECK(r.diag.warning_count() == 4);
  for (const char *what : {
           "warning: the runtimeCondition of plan 'Ignored' (id 1800000000000) is ignored",
           "warning: synchronisation 'Together' (id 1800000000040) of plan 'Ignored' (id 1800000000000) is ignored",
           "warning: the cardinalities [2..4] of entry point 'DefaultTask' (id 1800000000001) are ignored",
           "warning: transition 'Sync' (id 1800000000020) of plan 'Ignored' (id 1800000000000) is synchronised with "
           "others; the synchronisation is ignored",
       })
    CHECK(r.text.find(what) != std::string::npos);
  CHECK(r.text.find("[-Walica-ignored]") != std::string::npos);
}

TEST_CASE("alica: names that are no identifiers become unique identifiers", "[alica]") {
  std::string plan = R"({ "id" : 9, "name" : "my plan", "entryPoints" : [ { "id" : 10, "name" : "", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "go on", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 2, "name" : "go-on", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 3, "name" : "MISSING_NAME", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "TerminalState", "success" : true, "id" : 4, "name" : "state", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 5, "name" : "2nd", "confAbstractPlanWrappers" : [ ] } ],
    "transitions" : [
      { "id" : 20, "name" : "", "inState" : 1, "outState" : 2, "preCondition" : { "id" : 30, "name" : "" } },
      { "id" : 21, "name" : "", "inState" : 2, "outState" : 3, "preCondition" : { "id" : 31, "name" : "ok?" } },
      { "id" : 22, "name" : "", "inState" : 3, "outState" : 4, "preCondition" : null },
      { "id" : 23, "name" : "", "inState" : 1, "outState" : 5, "preCondition" : { "id" : 33, "name" : "ok!" } } ] })";
  Run r("my.pml", {{"my.pml", plan}});
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *c = r.chart("my_plan");
  REQUIRE(c);
  CHECK(place_names(*c) == std::vector<std::string>{"go_on", "go_on_2", "State3", "state_", "N2nd"});
  std::vector<std::string> functions;
  for (const auto &f : r.model.functions) functions.push_back(f.name);
  CHECK(functions == std::vector<std::string>{"Condition30", "ok_", "ok__33"});
  CHECK(!c->transitions[2].condition);  // no precondition: `when true`
}

TEST_CASE("alica: every fixture, truncated or damaged anywhere, is read without a crash", "[alica]") {
  auto files = fixture_files();
  // Every plan of the folder, read from disk as gfec reads it, well under a second each.
  for (const auto &[path, text] : files) {
    if (fs::path(path).extension() != ".pml") continue;
    auto start = std::chrono::steady_clock::now();
    test::Pipeline p((kFixtures / path).string(), RealFileSystem());
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    INFO(path);
    CHECK(ms < 250);
    for (const auto &d : p.diag.all()) CHECK(d.range.end <= p.sources.file(d.range.file).text().size());
  }
  // Master.pml cut at every 7th byte, and with one byte changed at every 13th: each a located
  // diagnostic or a clean read, never a crash.
  const std::string &master = files.at("plans/Master.pml");
  auto read = [&](const std::string &text) {
    MemoryFileSystem mem;
    for (const auto &[path, t] : files) mem.add(path, t);
    mem.add("plans/Master.pml", text);
    test::Pipeline p("plans/Master.pml", mem);
    for (const auto &d : p.diag.all()) REQUIRE(d.range.end <= p.sources.file(d.range.file).text().size());
  };
  for (std::size_t n = 0; n < master.size(); n += 7) read(master.substr(0, n));
  for (std::size_t n = 0; n < master.size(); n += 13)
    for (char c : {'"', '{', '[', '1', ','}) {
      std::string damaged = master;
      damaged[n] = c;
      read(damaged);
    }
}

TEST_CASE("alica: ids above 2^53 are quoted exactly, never rounded", "[alica]") {
  // 2^63 - 1 and 2^62 + 1: as doubles both would round (to 2^63 and 2^62).
  std::string plan = R"({ "id" : 9223372036854775807, "name" : "Huge",
    "entryPoints" : [ { "id" : 4611686018427387905, "name" : "", "state" : 4611686018427387907 } ],
    "states" : [ { "type" : "State", "id" : 4611686018427387907, "name" : "Spin", "confAbstractPlanWrappers" : [ ] } ],
    "transitions" : [ { "id" : 4611686018427387909, "name" : "Again", "inState" : 4611686018427387907,
                        "outState" : 4611686018427387907, "preCondition" : null } ] })";
  Run r("huge.pml", {{"huge.pml", plan}});
  INFO(r.text);
  CHECK(r.text.find("huge.pml:4:23: error: transition from state 'Spin' to itself [self-transition]") !=
        std::string::npos);
  CHECK(r.text.find("note: this is ALICA transition 'Again' (id 4611686018427387909) of plan 'Huge' (id "
                    "9223372036854775807)") != std::string::npos);
}

TEST_CASE("alica: the folder layouts of ALICA's own repositories are found, as ALICA's engine finds them", "[alica]") {
  // tests/alica/layout/etc: plans/, behaviours/, conditions/, placeholders/, tasks/, with a plan
  // type and a plan in plans/sub/ whose paths are stale. Read from disk, as gfec reads it.
  fs::path etc = kFixtures / "layout" / "etc";
  test::Pipeline p((etc / "plans" / "Patrol.pml").string(), RealFileSystem());
  const LoadResult &loaded = p.loaded;
  const model::Model &model = p.model;
  const Diagnostics &diag = p.diag;
  const std::string text = p.text();
  INFO(text);
  REQUIRE(!diag.has_errors());
  auto read = [&](const std::string &suffix) {
    for (const auto &p : loaded.paths)
      if (p.size() >= suffix.size() && p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0) return true;
    return false;
  };
  // "Look.beh#1900000001000" beside etc/plans/Patrol.pml is etc/behaviours/Look.beh: the nearer
  // etc/plans/Look.beh (the behaviour's interface) lacks that id; "ConditionRepository.cnd"
  // is etc/conditions/; SweepLeft.pml says it lives in "old" and names "Behaviour/Turn.beh", which
  // only the search below etc/ finds (as etc/behaviours/Turn.beh).
  CHECK(read("layout/etc/behaviours/Look.beh"));
  CHECK(read("layout/etc/conditions/ConditionRepository.cnd"));
  CHECK(read("layout/etc/plans/sub/Sweeps.pty"));
  CHECK(read("layout/etc/plans/sub/SweepLeft.pml"));
  CHECK(read("layout/etc/behaviours/Turn.beh"));
  const model::Chart *patrol = nullptr;
  for (const auto &c : model.charts)
    if (c.name == "Patrol") patrol = &c;
  REQUIRE(patrol);
  // "init" is the name of the engine's init function: renamed. A placeholder runs nothing.
  CHECK(place_names(*patrol) == std::vector<std::string>{"init_", "Wait", "Sweep", "Done"});
  CHECK(patrol->places[2].runs.valid());
  REQUIRE(patrol->transitions.size() == 3);
  // The designer names transitions by their ids: no name of the user's. AlwaysTrueCondition is
  // `true`, AnyChildSuccess on a state running an fsm `succeeded(Sweep)`; others are functions.
  CHECK(!patrol->transitions[0].named);
  REQUIRE(patrol->transitions[0].condition);
  CHECK(patrol->transitions[0].condition->kind == model::Expr::Kind::Bool);
  CHECK(patrol->transitions[0].condition->bool_value);
  REQUIRE(patrol->transitions[2].condition);
  CHECK(patrol->transitions[2].condition->kind == model::Expr::Kind::Succeeded);
  std::vector<std::string> functions;
  for (const auto &f : model.functions) functions.push_back(f.name);
  CHECK(functions == std::vector<std::string>{"Look", "Turn", "Turned", "Ready"});
  // What gfec ignores is a located warning, each once, in the file that holds it.
  CHECK(diag.warning_count() == 5);
  for (const char *what : {
           "layout/etc/plans/Patrol.pml:54:28: warning: state 'Wait' (id 1900000000011) of plan 'Patrol' (id "
           "1900000000000) holds the placeholder 'Anything.plc#1900000003000', which is ignored",
           "layout/etc/behaviours/Look.beh:2:18: warning: the blackboard of behaviour 'Look' (id 1900000001000) is "
           "ignored",
           "layout/etc/conditions/ConditionRepository.cnd:23:22: warning: the blackboard inputs of condition 'Ready' "
           "(id 1900000002002) are ignored",
           "layout/etc/plans/sub/Sweeps.pty:6:17: warning: the variables of plan type 'Sweeps' (id 1900000004000) "
           "are ignored",
           "layout/etc/plans/sub/Sweeps.pty:14:24: warning: the variableBindings of plan type 'Sweeps' (id "
           "1900000004000) are ignored",
       })
    CHECK(text.find(what) != std::string::npos);
}

TEST_CASE("alica: the search below the plans' root walks the loader's file system, never the disk behind it",
          "[alica]") {
  // The same plan in memory: the stale "Behaviour/Turn.beh" is found by the search below etc/,
  // through FileSystem::walk, as on disk (an editor's unsaved buffers are found the same way).
  Run r("layout/etc/plans/Patrol.pml");
  INFO(r.text);
  CHECK(r.diag.error_count() == 0);
  CHECK(std::find(r.loaded.paths.begin(), r.loaded.paths.end(), "layout/etc/behaviours/Turn.beh") !=
        r.loaded.paths.end());
  // Without the file in memory the search finds nothing, though the fixture is on disk: a
  // located error at the reference.
  MemoryFileSystem mem;
  for (const auto &[path, t] : fixture_files())
    if (path != "layout/etc/behaviours/Turn.beh") mem.add(path, t);
  test::Pipeline without("layout/etc/plans/Patrol.pml", mem);
  INFO(without.text());
  CHECK(without.diag.error_count() == 1);
  CHECK(without.text().find("layout/etc/plans/sub/SweepLeft.pml:33:28: error: cannot find 'Behaviour/Turn.beh', "
                            "referenced here [alica-reference]") != std::string::npos);
}

TEST_CASE("alica: a mistyped id in a repository suggests the element with the closest id", "[alica]") {
  std::string patrol = test::read_file((kFixtures / "layout/etc/plans/Patrol.pml").string());
  std::size_t at = patrol.find("ConditionRepository.cnd#1900000002002");
  REQUIRE(at != std::string::npos);
  patrol.replace(at, std::string("ConditionRepository.cnd#1900000002002").size(),
                 "ConditionRepository.cnd#1900000002012");
  Run r("layout/etc/plans/Typo.pml", {{"layout/etc/plans/Typo.pml", patrol}});
  INFO(r.text);
  CHECK(r.diag.error_count() == 1);
  CHECK(r.text.find("layout/etc/plans/Typo.pml:125:21: error: 'layout/etc/conditions/ConditionRepository.cnd' has "
                    "no element with id 1900000002012 [alica-reference]") != std::string::npos);
  CHECK(r.text.find("layout/etc/conditions/ConditionRepository.cnd:22:5: note: did you mean 'Ready' (id "
                    "1900000002002), which the file holds?") != std::string::npos);
}

TEST_CASE("alica: ALICA's other files given to gfec say what they are, at their first character", "[alica]") {
  for (auto [file, kind] : {std::pair{"layout/etc/behaviours/Look.beh", "an ALICA behaviour"},
                            std::pair{"layout/etc/plans/sub/Sweeps.pty", "an ALICA plan type"},
                            std::pair{"layout/etc/conditions/ConditionRepository.cnd", "an ALICA condition repository"},
                            std::pair{"layout/etc/placeholders/Anything.plc", "an ALICA placeholder"},
                            std::pair{"layout/etc/tasks/taskrepository.tsk", "an ALICA task repository"}}) {
    Run r(file);
    INFO(r.text);
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.rfind(fmt::format("{}:1:1: error: '{}' is not an ALICA plan", file, file), 0) == 0);
    CHECK(r.text.find(fmt::format("note: this is {}; gfec compiles plans (.pml)", kind)) != std::string::npos);
  }
  // An XML file of the older designer, whatever its kind.
  Run xml("old.pty", {{"old.pty", "<?xml version=\"1.0\" encoding=\"ASCII\"?>\n<alica:PlanType id=\"1\"/>\n"}});
  CHECK(xml.diag.error_count() == 1);
  CHECK(xml.text.find("old.pty:1:1: error: this is an XML file of ALICA's older Eclipse designer") !=
        std::string::npos);
}

TEST_CASE("alica: names the engine, C or C++ reserve, and names that are ids, become other identifiers", "[alica]") {
  std::string plan = R"({ "id" : 9, "name" : "new", "entryPoints" : [ { "id" : 10, "name" : "10", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "init", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 2, "name" : "run", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 3, "name" : "2", "confAbstractPlanWrappers" : [ ] },
                 { "type" : "State", "id" : 4, "name" : "uint8_t", "confAbstractPlanWrappers" : [ ] } ],
    "transitions" : [
      { "id" : 20, "name" : "20", "inState" : 1, "outState" : 2, "preCondition" : { "id" : 30, "name" : "30" } },
      { "id" : 21, "name" : "class", "inState" : 2, "outState" : 3, "preCondition" : { "id" : 31, "name" : "NULL" } },
      { "id" : 22, "name" : "", "inState" : 3, "outState" : 4, "preCondition" : null } ] })";
  Run r("new.pml", {{"new.pml", plan}});
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *c = r.chart("new_");
  REQUIRE(c);
  CHECK(place_names(*c) == std::vector<std::string>{"init_", "run_", "State3", "uint8_t_"});
  CHECK(!c->transitions[0].named);
  CHECK(c->transitions[1].name == "class_");
  std::vector<std::string> functions;
  for (const auto &f : r.model.functions) functions.push_back(f.name);
  CHECK(functions == std::vector<std::string>{"Condition30", "NULL_"});
}

TEST_CASE("alica: a child condition gfec cannot read from a sub-chart is a function, with a warning", "[alica]") {
  // State 'Drive' runs only a behaviour: ALICA's AllChildSuccess there asks whether the behaviour
  // succeeded, which gfec does not model.
  std::string plan = R"({ "id" : 9, "name" : "Go", "entryPoints" : [ { "id" : 10, "name" : "", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "Drive", "abstractPlans" : [ "Drive.beh#5" ] },
                 { "type" : "TerminalState", "success" : true, "id" : 2, "name" : "There" } ],
    "transitions" : [ { "id" : 20, "name" : "Arrived", "inState" : 1, "outState" : 2,
                        "preCondition" : { "id" : 30, "name" : "AllChildSuccess" } } ] })";
  Run r("go.pml", {{"go.pml", plan}, {"Drive.beh", R"({ "id" : 5, "name" : "Drive" })"}});
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  CHECK(r.diag.warning_count() == 1);
  CHECK(r.text.find("go.pml:5:42: warning: transition 'Arrived' (id 20) of plan 'Go' (id 9) tests AllChildSuccess of "
                    "state 'Drive', but it runs no plan, and gfec does not model the success or failure of behaviours: "
                    "the condition becomes the sensing function 'AllChildSuccess()' of the robot library "
                    "[-Walica-ignored]") != std::string::npos);
  const model::Chart *c = r.chart("Go");
  REQUIRE(c);
  REQUIRE(c->transitions[0].condition);
  CHECK(c->transitions[0].condition->kind == model::Expr::Kind::Call);
}

TEST_CASE("alica: a wrapper's blackboard key mapping is a located warning", "[alica]") {
  std::string plan = R"({ "id" : 9, "name" : "Go", "entryPoints" : [ { "id" : 10, "name" : "", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "Drive", "confAbstractPlanWrappers" : [
      { "id" : 11, "name" : "", "abstractPlan" : "Drive.beh#5",
        "keyMapping" : { "input" : [ { "childKey" : "goal", "parentKey" : "target" } ], "output" : [ ] } } ] } ],
    "transitions" : [ ] })";
  Run r("go.pml", {{"go.pml", plan}, {"Drive.beh", R"({ "id" : 5, "name" : "Drive" })"}});
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  CHECK(r.diag.warning_count() == 1);
  CHECK(r.text.find("go.pml:4:24: warning: the blackboard key mapping of 'Drive.beh#5' in state 'Drive' (id 1) of "
                    "plan 'Go' (id 9) is ignored: gfec has no blackboard [-Walica-ignored]") != std::string::npos);
}

TEST_CASE("alica json: a UTF-8 byte order mark before the document is skipped", "[alica]") {
  alica::JsonError error;
  auto v = alica::parse_json("\xef\xbb\xbf{ \"id\" : 1 }", error);
  REQUIRE(v);
  CHECK(v->begin == 3);
  CHECK(v->find("id")->text == "1");
  CHECK(!alica::parse_json("\xef\xbb{ }", error));
}

TEST_CASE("alica: plans nest at most 200 deep, deeper is an error at the reference, not a crash", "[alica]") {
  // c<i>.pml has one state that runs c<i+1>.pml: a chain of `n` plans, each one deeper.
  auto chain = [](int n) {
    std::map<std::string, std::string> files;
    for (int i = 0; i < n; ++i) {
      std::string runs = i + 1 < n ? fmt::format("\"c{}.pml#{}\"", i + 1, 1000 + i + 1) : "";
      files[fmt::format("c{}.pml", i)] = fmt::format(
          R"({{ "id" : {}, "name" : "c{}", "entryPoints" : [ {{ "id" : {}, "name" : "", "state" : {} }} ],
  "states" : [ {{ "type" : "State", "id" : {}, "name" : "Run", "abstractPlans" : [ {} ] }} ],
  "transitions" : [ ] }})",
          1000 + i, i, 5000 + i, 9000 + i, 9000 + i, runs);
    }
    return files;
  };
  SECTION("200 plans below the compiled one are read") {
    Run r("c0.pml", chain(201));
    INFO(r.text);
    CHECK(!r.diag.has_errors());
    CHECK(r.chart("c200") != nullptr);
  }
  SECTION("the reference to the 201st is an error where it is written, and nothing below is read") {
    // 3000 plans crashed gfec (a stack overflow) before the limit.
    Run r("c0.pml", chain(3000));
    INFO(r.text.substr(0, 2000));
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("c200.pml:2:85: error: plans nested more than 200 deep: plan 'c201' (id 1201) would run 201 "
                      "levels below the compiled plan [alica-reference]") != std::string::npos);
    CHECK(std::find(r.loaded.paths.begin(), r.loaded.paths.end(), "c202.pml") == r.loaded.paths.end());
  }
}

TEST_CASE("alica: control characters of names and references are escaped in messages", "[alica]") {
  // As every message spells them (support/escape.h): <U+000A>, <U+001B>.
  std::string plan =
      R"({ "id" : 9, "name" : "Esc\u001b]0;pwned\u0007", "entryPoints" : [ { "id" : 10, "name" : "", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "A\u001b[31m", "abstractPlans" : [ "Foo\u0000.beh#1" ] },
                 { "type" : "State", "id" : 2, "name" : "B", "abstractPlans" : [ "Bar\n::error::.beh#2" ] } ],
    "transitions" : [ { "id" : 20, "name" : "T\nfake.pml:1:1: error: injected", "inState" : 1, "outState" : 7,
                        "preCondition" : null } ] })";
  Run r("esc.pml", {{"esc.pml", plan}});
  INFO(r.text);
  CHECK(r.diag.error_count() == 3);
  CHECK(r.text.find('\x1b') == std::string::npos);
  CHECK(r.text.find('\0') == std::string::npos);
  CHECK(r.text.find('\x07') == std::string::npos);
  // Every line is one of gfec's, a diagnostic or a quoted source line: none is forged by a name.
  std::size_t start = 0;
  for (std::size_t end; (end = r.text.find('\n', start)) != std::string::npos; start = end + 1)
    CHECK((r.text.compare(start, 8, "esc.pml:") == 0 || r.text[start] == ' '));
  CHECK(r.text.find("error: 'Foo<U+0000>.beh#1' names a file with a control character in its name "
                    "[alica-reference]") != std::string::npos);
  CHECK(r.text.find("error: 'Bar<U+000A>::error::.beh#2' names a file with a control character") != std::string::npos);
  CHECK(r.text.find("error: transition 'T<U+000A>fake.pml:1:1: error: injected' (id 20) of plan "
                    "'Esc<U+001B>]0;pwned<U+0007>' (id 9) names outState 7, which the plan has no state for") !=
        std::string::npos);
}

TEST_CASE("alica: names the C headers reserve get '_' appended, as the validator would refuse them", "[alica]") {
  std::string states;
  int id = 1;
  for (const char *name :
       {"INT_MAX", "UINT32_MAX", "SIZE_MAX", "UINT64_C", "INT8_MAX", "stdout", "_Bool", "int_least8_t", "FLT_MAX"}) {
    states += fmt::format(R"({}{{ "type" : "State", "id" : {}, "name" : "{}" }})", id > 1 ? ", " : "", id, name);
    ++id;
  }
  std::string transitions;
  for (int i = 1; i + 1 < id; ++i)
    transitions += fmt::format(R"({}{{ "id" : {}, "name" : "", "inState" : {}, "outState" : {},
      "preCondition" : {{ "id" : {}, "name" : "{}" }} }})",
                               i > 1 ? ", " : "", 100 + i, i, i + 1, 200 + i, i == 1 ? "EOF" : "LLONG_MIN");
  std::string plan = fmt::format(R"({{ "id" : 9, "name" : "Limits", "entryPoints" : [ {{ "id" : 10, "state" : 1 }} ],
    "states" : [ {} ], "transitions" : [ {} ] }})",
                                 states, transitions);
  Run r("limits.pml", {{"limits.pml", plan}});
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *c = r.chart("Limits");
  REQUIRE(c);
  // <float.h> reserves FLT_ followed by any capitals and '_': FLT_MAX_ is taken too.
  CHECK(place_names(*c) == std::vector<std::string>{"INT_MAX_", "UINT32_MAX_", "SIZE_MAX_", "UINT64_C_", "INT8_MAX_",
                                                    "stdout_", "g_Bool", "int_least8_t_", "FLT_MAX_x"});
  std::vector<std::string> functions;
  for (const auto &f : r.model.functions) functions.push_back(f.name);
  REQUIRE(functions.size() >= 3);
  CHECK(functions[0] == "EOF_");
  CHECK(functions[1] == "LLONG_MIN_");
  CHECK(functions[2] == "LLONG_MIN__203");  // the same name again: its id appended
}

TEST_CASE("alica: the picture of a plan labels transitions with the condition, not its JSON", "[alica]") {
  Run r("plans/Fetch.pml");
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  const model::Chart *c = r.chart("Fetch");
  REQUIRE(c);
  std::ostringstream picture;
  dot::chart_picture(r.model, *c, picture);
  const std::string dot = picture.str();
  INFO(dot);
  CHECK(dot.find("1. Go2Grab: Arrived()") != std::string::npos);
  CHECK(dot.find("1. Grab2Got: Holding()") != std::string::npos);
  CHECK(dot.find("DriveToItem();") != std::string::npos);  // the state's action: a call, not the reference
  CHECK(dot.find("\"id\"") == std::string::npos);
  CHECK(dot.find("#1700000000001") == std::string::npos);
}

TEST_CASE("alica: ids that are no integers, unpaired surrogates and empty references", "[alica]") {
  SECTION("a state id 1.5 or 1e3 is an error at the id saying ids are integers") {
    std::string plan = R"({ "id" : 9, "name" : "P", "entryPoints" : [ { "id" : 10, "name" : "E", "state" : 2 } ],
    "states" : [ { "type" : "State", "id" : 1.5, "name" : "Go" }, { "type" : "State", "id" : 2, "name" : "Stop" } ],
    "transitions" : [ { "id" : 20, "name" : "T", "inState" : 2, "outState" : 1e3, "preCondition" : null } ] })";
    Run r("ids.pml", {{"ids.pml", plan}});
    INFO(r.text);
    CHECK(r.diag.error_count() == 2);
    CHECK(r.text.find("ids.pml:2:45: error: the id of state 'Go' of plan 'P' (id 9) is 1.5, which is no id: ALICA's "
                      "ids are 64-bit integers [alica-format]") != std::string::npos);
    CHECK(r.text.find("ids.pml:3:78: error: the outState of transition 'T' (id 20) of plan 'P' (id 9) is 1e3, which "
                      "is no id: ALICA's ids are 64-bit integers [alica-format]") != std::string::npos);
    // An entry point's state: "starts in state (none)" was all it said.
    std::string entry = plan;
    entry.replace(entry.find("\"state\" : 2"), 11, "\"state\" : 2.0");
    Run e("entry.pml", {{"entry.pml", entry}});
    INFO(e.text);
    CHECK(e.text.find("entry.pml:1:82: error: the state of entry point 'E' (id 10) of plan 'P' (id 9) is 2.0, which is "
                      "no id: ALICA's ids are 64-bit integers [alica-format]") != std::string::npos);
    CHECK(e.text.find("(none)") == std::string::npos);
    // Beyond 64 bits: no id either (one more than INT64_MAX; INT64_MIN itself is one).
    std::string big = plan;
    auto swap = [&](const std::string &from, const std::string &to) { big.replace(big.find(from), from.size(), to); };
    swap("\"id\" : 1.5", "\"id\" : 9223372036854775808");
    swap("\"outState\" : 1e3", "\"outState\" : -9223372036854775808");
    Run b("big.pml", {{"big.pml", big}});
    INFO(b.text);
    CHECK(b.diag.error_count() == 2);
    CHECK(b.text.find("error: the id of state 'Go' of plan 'P' (id 9) is 9223372036854775808, which is no id: "
                      "ALICA's ids are 64-bit integers [alica-format]") != std::string::npos);
    CHECK(b.text.find("the outState of transition 'T' (id 20) of plan 'P' (id 9) is -9223372036854775808, which is "
                      "no id") == std::string::npos);
    // The ids that only messages quote too.
    big = plan;
    swap("\"id\" : 9,", "\"id\" : 99999999999999999999,");
    Run p("plan_id.pml", {{"plan_id.pml", big}});
    INFO(p.text);
    CHECK(p.text.find("plan_id.pml:1:10: error: the id of plan 'P' is 99999999999999999999, which is no id: ALICA's "
                      "ids are 64-bit integers [alica-format]") != std::string::npos);
  }
  SECTION("a high surrogate before an escape that is no low surrogate keeps that character") {
    alica::JsonError error;
    auto v = alica::parse_json(R"(["\ud800\u0041", "\ud83d\ude00", "\udc00x", "\ud800"])", error);
    REQUIRE(v);
    REQUIRE(v->items.size() == 4);
    CHECK(v->items[0].text == "\xef\xbf\xbd"
                              "A");
    CHECK(v->items[1].text == "\xf0\x9f\x98\x80");
    CHECK(v->items[2].text == "\xef\xbf\xbdx");
    CHECK(v->items[3].text == "\xef\xbf\xbd");
  }
  SECTION("an empty abstractPlan is an error at it") {
    std::string plan = R"({ "id" : 9, "name" : "P", "entryPoints" : [ { "id" : 10, "name" : "", "state" : 1 } ],
    "states" : [ { "type" : "State", "id" : 1, "name" : "Go",
                   "confAbstractPlanWrappers" : [ { "id" : 11, "name" : "", "abstractPlan" : "" } ] } ],
    "transitions" : [ ] })";
    Run r("empty.pml", {{"empty.pml", plan}});
    INFO(r.text);
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("empty.pml:3:94: error: state 'Go' (id 1) of plan 'P' (id 9) wraps an empty \"abstractPlan\": "
                      "ALICA writes a reference as \"File.ext#id\" [alica-reference]") != std::string::npos);
  }
}

// The cases below come from running gfec over the plan folders ALICA publishes (docs/alica.md,
// "Running gfec over a folder of plans"); their fixtures are tests/alica/published/, written for
// gfec in the formats those folders use.

TEST_CASE("alica json: a member named twice is kept, with where both names are", "[alica]") {
  std::string text = R"({ "a" : 1, "b" : [ 2 ], "a" : 1, "b" : [ 3 ] })";
  alica::JsonError error;
  auto v = alica::parse_json(text, error);
  REQUIRE(v);
  REQUIRE(v->duplicates.size() == 2);
  const auto &a = v->duplicates[0];
  CHECK(a.first == 0);
  CHECK(a.second == 2);
  CHECK(text.substr(a.first_key_begin, a.first_key_end - a.first_key_begin) == "\"a\"");
  CHECK(a.first_key_begin == 2);
  CHECK(a.key_begin == 24);
  CHECK(alica::same_json(v->members[0].second, v->members[2].second));
  CHECK(!alica::same_json(v->members[1].second, v->members[3].second));
  CHECK(v->find("a") == &v->members[0].second);  // the first counts, as in ALICA's engine
  SECTION("in an object too large to compare every pair of names") {
    std::string big = "{";
    for (int i = 0; i < 100; ++i) big += fmt::format("\"k{}\" : {}, ", i, i);
    big += "\"k5\" : 5, \"k99\" : 0 }";
    auto b = alica::parse_json(big, error);
    REQUIRE(b);
    REQUIRE(b->duplicates.size() == 2);
    CHECK(b->duplicates[0].first == 5);
    CHECK(b->duplicates[0].second == 100);
    CHECK(b->duplicates[1].first == 99);
    CHECK(b->duplicates[1].second == 101);
    CHECK(big.substr(b->duplicates[1].key_begin, 5) == "\"k99\"");
  }
}

TEST_CASE("alica: a member named twice is located, an error when gfec reads it and the second differs", "[alica]") {
  SECTION("repeated, or not read by gfec: warnings at the second name, a note at the first") {
    Run r("published/etc/plans/Twice.pml");
    INFO(r.text);
    REQUIRE(!r.diag.has_errors());
    CHECK(r.diag.warning_count() == 3);
    CHECK(r.text.find("published/etc/plans/Twice.pml:22:7: warning: member \"positionWeb\" is given a second time "
                      "in this object, with another value; gfec does not read this member here [-Wduplicate-key]") !=
          std::string::npos);
    CHECK(r.text.find("published/etc/plans/Twice.pml:18:7: note: the first \"positionWeb\" is here") !=
          std::string::npos);
    CHECK(r.text.find("published/etc/plans/Twice.pml:27:7: warning: member \"name\" is given a second time in this "
                      "object, with the same value [-Wduplicate-key]") != std::string::npos);
    CHECK(r.text.find("published/etc/plans/Twice.pml:31:3: warning: member \"comment\" is given a second time in "
                      "this object, with another value; gfec does not read this member here") != std::string::npos);
    // The note names the element the duplicate is in, as for the validator's diagnostics.
    CHECK(r.text.find("note: this is ALICA state 'Idle' (id 2100000000000000042)") != std::string::npos);
    CHECK(r.chart("Twice") != nullptr);
  }
  SECTION("a member gfec reads, given again with another value: an error, whichever gfec took") {
    Run r("published/etc/plans/Conflict.pml");
    INFO(r.text);
    CHECK(r.diag.error_count() == 1);
    CHECK(r.text.find("published/etc/plans/Conflict.pml:9:7: error: member \"state\" is given a second time in this "
                      "object, with another value: gfec reads the first, as ALICA's engine does, but ALICA's plan "
                      "designer keeps this one [conflicting-key]") != std::string::npos);
    CHECK(r.text.find("published/etc/plans/Conflict.pml:7:7: note: the first \"state\" is here") != std::string::npos);
  }
  SECTION("-Wno-duplicate-key silences the warnings, not the error") {
    WarningOptions quiet;
    quiet.set(Warning::DuplicateKey, false);
    for (const char *plan : {"published/etc/plans/Twice.pml", "published/etc/plans/Conflict.pml"}) {
      MemoryFileSystem mem;
      for (const auto &[path, t] : fixture_files()) mem.add(path, t);
      SourceManager sources;
      Diagnostics diag(quiet);
      load_program(plan, {}, mem, sources, diag);
      std::string text;
      for (const auto &d : diag.all()) text += render_text(d, sources);
      INFO(text);
      CHECK(diag.warning_count() == 0);
      CHECK(diag.error_count() == (std::string(plan).find("Conflict") != std::string::npos ? 1u : 0u));
    }
  }
}

TEST_CASE("alica: a preCondition beside a condition reference decides nothing, and takes no function name", "[alica]") {
  // The designer of ALICA's current repositories writes both; the reference is what the engine
  // evaluates. The warning about the preCondition's quantifiers named a function 'Ready()' that
  // no transition calls, and that name then went to the repository's 'Ready' as 'Ready_12'.
  Run r("published/etc/plans/Leftover.pml");
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  std::vector<std::string> functions;
  for (const auto &f : r.model.functions) functions.push_back(f.name);
  CHECK(functions == std::vector<std::string>{"Wait", "Armed", "Ready"});
  CHECK(r.diag.warning_count() == 1);
  CHECK(r.text.find("published/etc/plans/Leftover.pml:123:24: warning: the quantifiers of condition (id "
                    "2100000000000000030) are ignored: the transition's \"condition\", 'ConditionRepository.cnd#11', "
                    "decides when it fires [-Walica-ignored]") != std::string::npos);
  const model::Chart *c = r.chart("Leftover");
  REQUIRE(c);
  REQUIRE(c->transitions.size() == 2);
  CHECK(c->transitions[1].condition->kind == model::Expr::Kind::Call);
}

TEST_CASE("alica: --emit=json writes a plan's conditions and actions as the model's expressions, not its JSON",
          "[alica]") {
  for (const char *plan : {"published/etc/plans/Leftover.pml", "plans/Fetch.pml"}) {
    Run r(plan);
    INFO(r.text);
    REQUIRE(!r.diag.has_errors());
    std::string name = fs::path(plan).stem().string();
    EmitOptions o;
    o.output_path = name + ".json";
    o.source_name = plan;
    o.chart = r.model.charts.id_of(*r.chart(name));
    std::string json = emit_to_memory(*make_json_backend(), r.model, o).at(0).contents;
    INFO(json.substr(0, 3000));
    // A condition's range is a reference string or a whole preCondition object; an action's, the
    // behaviour's reference: none of that JSON may stand for an expression or a statement.
    CHECK(json.find(".cnd#") == std::string::npos);
    CHECK(json.find(".beh#") == std::string::npos);
    CHECK(json.find("\"text\": \"{") == std::string::npos);
    CHECK(json.find("\"when\": \"{") == std::string::npos);
    CHECK(json.find("\\\"") == std::string::npos);  // no JSON quoted inside a string
    if (name == "Leftover") {
      CHECK(json.find("\"when\": \"Armed()\"") != std::string::npos);
      CHECK(json.find("\"text\": \"Ready()\"") != std::string::npos);
      CHECK(json.find("\"text\": \"Wait();\"") != std::string::npos);
    } else {
      CHECK(json.find("\"when\": \"Arrived()\"") != std::string::npos);
      CHECK(json.find("\"text\": \"DriveToItem();\"") != std::string::npos);
    }
  }
}

TEST_CASE("alica: a plan that cannot be found is never said to be the plan that references it", "[alica]") {
  Run r("published/etc/plans/Serial.pml");
  INFO(r.text);
  CHECK(r.diag.error_count() == 1);
  CHECK(r.text.find("error: cannot find 'SerialPart.pml', referenced here [alica-reference]") != std::string::npos);
  CHECK(r.text.find("did you mean 'Serial.pml'") == std::string::npos);
}

TEST_CASE("alica: a plan saved as one line of JSON is quoted around each diagnostic, not whole", "[alica]") {
  // Every diagnostic quoted the whole line: a minified plan with many of them printed the file once each.
  Run r("published/etc/plans/Minified.pml");
  INFO(r.text);
  REQUIRE(!r.diag.has_errors());
  REQUIRE(r.diag.warning_count() == 3);
  std::string plan = test::read_file((kFixtures / "published/etc/plans/Minified.pml").string());
  CHECK(r.text.size() < plan.size());
  // The key mapping of the state's wrapper: the caret under its '{', in the part of the line shown.
  std::size_t at = r.text.find("Minified.pml:1:870: warning: the blackboard key mapping of 'Wait.beh#");
  REQUIRE(at != std::string::npos);
  std::size_t line = r.text.find('\n', at) + 1, caret_line = r.text.find('\n', line) + 1;
  std::string quoted = r.text.substr(line, caret_line - 1 - line);
  std::string carets = r.text.substr(caret_line, r.text.find('\n', caret_line) - caret_line);
  CHECK(quoted.size() < 300);
  CHECK(quoted.rfind(" ...", 0) == 0);
  std::size_t caret = carets.find('^');
  REQUIRE(caret != std::string::npos);
  CHECK(quoted.compare(caret, 9, "{\"input\":") == 0);
  CHECK(plan.compare(869, 9, "{\"input\":") == 0);  // column 870 is that '{'
}

TEST_CASE("alica: a warning of the analyses names its element once, whether they run in the front end or after it",
          "[alica][pipeline]") {
  // Two transitions out of Wait, neither with a precondition: the second never fires (the
  // analyses' warning); Left's name given twice (the reader's). A language server runs the
  // analyses after the front end (Compilation::analyze); annotating all the diagnostics again
  // there would name the reader's element twice.
  MemoryFileSystem mem;
  mem.add("Fork.pml", R"({ "id" : 1900000000000, "name" : "Fork", "masterPlan" : false, "variables" : [],
  "entryPoints" : [ { "id" : 1900000000001, "name" : "Start", "task" : null, "state" : 1900000000002,
                      "plan" : 1900000000000 } ],
  "states" : [
    { "type" : "State", "id" : 1900000000002, "name" : "Wait", "entryPoint" : 1900000000001,
      "parentPlan" : 1900000000000, "outTransitions" : [ 1900000000020, 1900000000021 ], "inTransitions" : [] },
    { "type" : "State", "id" : 1900000000003, "name" : "Left", "name" : "Left", "parentPlan" : 1900000000000,
      "outTransitions" : [], "inTransitions" : [ 1900000000020 ] },
    { "type" : "State", "id" : 1900000000004, "name" : "Right", "parentPlan" : 1900000000000,
      "outTransitions" : [], "inTransitions" : [ 1900000000021 ] } ],
  "transitions" : [
    { "id" : 1900000000020, "name" : "ToLeft", "inState" : 1900000000002, "outState" : 1900000000003,
      "preCondition" : null },
    { "id" : 1900000000021, "name" : "ToRight", "inState" : 1900000000002, "outState" : 1900000000004,
      "preCondition" : null } ],
  "synchronisations" : [] }
)");
  auto text = [](const pipeline::Compilation &c) {
    std::string out;
    for (const auto &d : c.diag.all()) out += render_text(d, c.sources);
    return out;
  };
  auto count = [](const std::string &text, const std::string &what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  pipeline::FrontEndOptions options;  // the analyses on, as gfec runs them
  pipeline::Compilation whole(options);
  CHECK(whole.front_end("Fork.pml", mem));
  pipeline::Compilation later(options);
  REQUIRE(later.load_and_validate("Fork.pml", mem));
  CHECK(later.analysis_pending());
  const std::size_t front = later.diag.all().size();
  CHECK(later.analyze());
  CHECK(!later.analysis_pending());
  CHECK(later.analyze());  // once: a second call adds nothing
  CHECK(later.diag.all().size() == front + 1);
  const std::string all = text(later);
  INFO(all);
  CHECK(all == text(whole));
  CHECK(all.find("warning: transition 'ToRight' (Wait -> Right) can never fire") != std::string::npos);
  CHECK(count(all, "note: this is ALICA transition 'ToRight' (id 1900000000021)") == 1);
  CHECK(count(all, "(ALICA transition 'ToLeft' (id 1900000000020)") == 1);
  CHECK(front == 1);
  CHECK(count(all, "[-Wduplicate-key]") == 1);
  CHECK(count(all, "note: this is ALICA state 'Left' (id 1900000000003)") == 1);
}
