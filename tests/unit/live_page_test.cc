// The live page's recording and server (monitor/live/, docs/live.md "The live page"): ticks
// handed on by a decoder become frames the page appends, with the engine's tick numbers, losses,
// silence and the end; a team's robots are aligned tick by tick; the server answers on loopback
// only, with the page and its updates, while a decoder thread appends (clean when compiled with
// -fsanitize=thread).
#include "live_recording.h"
#include "live_server.h"

#include <catch2/catch.hpp>
#include <httplib.h>

#include <atomic>
#include <thread>

using gfec::live::LiveChart;
using gfec::live::LiveRecording;
using gfec::monitor::DecodedTick;
using nlohmann::json;

namespace {

LiveChart three_places() {
  LiveChart c;
  c.name = "Follow";
  c.kind = "sfc";
  c.file = "follow.sfc";
  c.period = 0.01;
  c.rows = {{"Start", "p0", false, "", -1}, {"Left", "p1", false, "", -1}, {"Right", "p2", false, "", -1}};
  c.source = "stdin";
  return c;
}

DecodedTick at(std::uint32_t tick, std::vector<std::uint32_t> activation, std::size_t robot = 0) {
  DecodedTick t;
  t.robot = robot;
  t.tick = tick;
  t.activation = std::move(activation);
  return t;
}

}  // namespace

TEST_CASE("live recording: ticks become frames, an update holds only what the page lacks", "[live]") {
  LiveRecording rec(three_places());
  CHECK(rec.page_data()["live"]["link"]["state"] == "waiting");
  rec.started(0);
  DecodedTick t1 = at(1, {1, 0, 0});
  t1.calls = {"Left() = false"};
  t1.has_calls = true;
  rec.tick(t1);
  rec.tick(at(2, {0, 1, 0}));
  json page = rec.page_data();
  CHECK(page["frames"] == 2);
  CHECK(page["active"] == json::parse("[[0,[0]],[1,[1]]]"));
  CHECK(page["live"]["link"]["state"] == "live");
  CHECK(page["calls"]["texts"] == json::array({"Left() = false"}));

  rec.tick(at(3, {0, 1, 0}));
  DecodedTick t4 = at(4, {0, 0, 1});
  t4.calls = {"Left() = false", "Right() = true"};
  t4.has_calls = true;
  rec.tick(t4);
  gfec::viewer::RecordingBuilder::Cursor c;
  c.frames = 2;
  c.events = page["events"].size();
  c.texts = {1};
  json u = rec.update(c);
  CHECK(u["frames"] == 4);
  // Frame 2 repeats frame 1's activation: no entry; frame 3 changes it.
  CHECK(u["active"] == json::parse("[[3,[2]]]"));
  // The page holds the first call text; the new one is text 1. Frame 2 made no call, as frame 1.
  CHECK(u["calls"]["texts_from"] == 1);
  CHECK(u["calls"]["texts"] == json::array({"Right() = true"}));
  CHECK(u["calls"]["ticks"] == json::parse("[[3,[0,1]]]"));
  CHECK(u["events"].empty());
}

TEST_CASE("live recording: a stream joined late and a gap keep the engine's tick numbers", "[live]") {
  LiveRecording rec(three_places());
  rec.tick(at(500, {1, 0, 0}));
  rec.tick(at(501, {1, 0, 0}));
  rec.lost(0, 3, "bad checksum");
  rec.tick(at(505, {0, 1, 0}));
  rec.tick(at(1, {0, 0, 1}));  // the engine started again
  json page = rec.page_data();
  CHECK(page["frames"] == 4);
  // tick = frame + 1 + offset: 500, 501, then 505, then 1.
  CHECK(page["ticks"] == json::parse("[[0,499],[2,502],[3,-3]]"));
  CHECK(page["live"]["link"]["lost_ticks"] == 3);
  CHECK(page["live"]["link"]["losses"] == 1);
  REQUIRE(page["events"].size() == 1);
  CHECK(page["events"][0] == json::parse(R"([2,"lost","3 ticks lost: bad checksum"])"));
}

TEST_CASE("live recording: silence and the end are the link's state", "[live]") {
  LiveRecording rec(three_places());
  rec.tick(at(1, {1, 0, 0}));
  rec.silent(2.5);
  CHECK(rec.update({1, 0, {0}})["link"]["silent"] == 2.5);
  rec.tick(at(2, {1, 0, 0}));
  CHECK(rec.update({2, 0, {0}})["link"]["silent"] == 0);
  DecodedTick done = at(3, {0, 0, 0});
  done.status = "succeeded";
  rec.tick(done);
  rec.ended("end of file");
  json u = rec.update({2, 0, {0}});
  CHECK(u["link"]["state"] == "ended");
  CHECK(u["link"]["ended"] == "end of file");
  CHECK(u["status"] == json::parse(R"([[2,"succeeded"]])"));
  REQUIRE(u["events"].size() == 2);
  CHECK(u["events"][0] == json::parse(R"([2,"status","succeeded"])"));
  CHECK(u["events"][1][1] == "note");
}

TEST_CASE("live recording: a team's robots are aligned tick by tick, each in its rows", "[live]") {
  LiveChart chart = three_places();
  LiveRecording rec(chart, 2);
  rec.started(0);
  rec.started(1);
  rec.tick(at(1, {1, 0, 0}, 0));
  CHECK(rec.frames() == 0);  // robot 1's tick 1 is not there yet
  rec.tick(at(1, {0, 0, 1}, 1));
  CHECK(rec.frames() == 1);
  rec.tick(at(2, {0, 1, 0}, 1));
  rec.tick(at(3, {0, 1, 0}, 1));
  CHECK(rec.frames() == 1);
  rec.tick(at(3, {0, 0, 1}, 0));  // robot 0's tick 2 was lost: frame 2 shows robot 1 alone
  CHECK(rec.frames() == 3);
  json page = rec.page_data();
  REQUIRE(page["rows"].size() == 6);
  CHECK(page["rows"][3]["name"] == "robot 1/Start");
  CHECK(page["rows"][3]["robot"] == 1);
  CHECK(page["robots"].size() == 2);
  CHECK(page["active"] == json::parse("[[0,[0,5]],[1,[4]],[2,[2,4]]]"));
  // A robot that falls silent holds the team back no more than kTeamSlack ticks.
  for (std::uint32_t k = 4; k < 4 + gfec::live::kTeamSlack + 1; ++k) rec.tick(at(k, {1, 0, 0}, 0));
  CHECK(rec.frames() == 4);
}

TEST_CASE("live recording: a team's robot that ended is not waited for and stays in its last state", "[live]") {
  LiveRecording rec(three_places(), 2);
  rec.tick(at(1, {1, 0, 0}, 0));
  DecodedTick done = at(1, {0, 0, 1}, 1);
  done.status = "succeeded";
  rec.tick(done);
  CHECK(rec.frames() == 1);
  rec.tick(at(2, {0, 1, 0}, 0));  // robot 1's engine ended: it sends no tick 2
  rec.tick(at(3, {0, 1, 0}, 0));
  CHECK(rec.frames() == 3);
  json page = rec.page_data();
  CHECK(page["active"] == json::parse("[[0,[0,5]],[1,[1,5]]]"));
  CHECK(page["robots"][1]["status"] == json::parse(R"([[0,"succeeded"]])"));
}

TEST_CASE("live server: loopback only unless asked, the page and its updates over HTTP", "[live]") {
  using gfec::live::is_loopback;
  CHECK(is_loopback("127.0.0.1"));
  CHECK(is_loopback("127.1.2.3"));
  CHECK(is_loopback("::1"));
  CHECK(is_loopback("localhost"));
  CHECK_FALSE(is_loopback("0.0.0.0"));
  CHECK_FALSE(is_loopback("192.168.1.5"));
  CHECK_FALSE(is_loopback("127.0.0.1.evil.example"));
  std::string host;
  int port = -1;
  CHECK(gfec::live::parse_address("127.0.0.1:0", host, port).empty());
  CHECK((host == "127.0.0.1" && port == 0));
  CHECK(gfec::live::parse_address("[::1]:8080", host, port).empty());
  CHECK((host == "::1" && port == 8080));
  CHECK_FALSE(gfec::live::parse_address("127.0.0.1", host, port).empty());
  CHECK_FALSE(gfec::live::parse_address("127.0.0.1:70000", host, port).empty());

  LiveRecording rec(three_places());
  {
    gfec::live::LiveServer refused(rec);
    CHECK(refused.bind("0.0.0.0", 0, false).find("not a loopback address") != std::string::npos);
  }
  gfec::live::LiveServer server(rec);
  REQUIRE(server.bind("127.0.0.1", 0, false).empty());
  REQUIRE(server.port() > 0);
  CHECK(server.url() == "http://127.0.0.1:" + std::to_string(server.port()) + "/");
  server.start();

  // The decoder thread appends while HTTP threads read.
  std::atomic<bool> done{false};
  std::thread decoder([&] {
    rec.started(0);
    for (std::uint32_t k = 1; k <= 2000; ++k) rec.tick(at(k, {k % 3 == 0, k % 3 == 1, k % 3 == 2}));
    done = true;
  });
  httplib::Client client("127.0.0.1", server.port());
  long seen = 0;
  int polls = 0;
  while (seen < 2000 && polls < 10000) {
    auto res = client.Get(("/live?frames=" + std::to_string(seen) + "&events=0&texts=0").c_str());
    REQUIRE(res);
    REQUIRE(res->status == 200);
    json u = json::parse(res->body);
    // Every frame from `seen` on changes the activation, so the update holds exactly them.
    const long frames = u["frames"].get<long>();
    CHECK(u["active"].size() == static_cast<std::size_t>(frames - seen));
    if (!u["active"].empty()) CHECK(u["active"][0][0] == seen);
    seen = frames;
    ++polls;
  }
  decoder.join();
  CHECK(done);
  CHECK(seen == 2000);
  auto page = client.Get("/");
  REQUIRE(page);
  CHECK(page->status == 200);
  CHECK(page->body.find("id=\"gfec-data\"") != std::string::npos);
  CHECK(page->body.find("\"live\"") != std::string::npos);
  // Another site's name for this machine (DNS rebinding) is not answered.
  httplib::Headers other{{"Host", "attacker.example:" + std::to_string(server.port())}};
  auto refused = client.Get("/live", other);
  REQUIRE(refused);
  CHECK(refused->status == 403);
  server.stop();
}
