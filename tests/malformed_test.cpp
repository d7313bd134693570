// The malformed-input table (tests/malformed/expected.tsv): every file is rejected by the
// real loader and by `pathtracer render` (exit 1, no crash) with a message that names
// the broken file, a line, byte offset or pixel in it, and the problem. Meshes and
// images are loaded the way a scene reaches them: through a <Mesh> or <Environment>.
// docs/reliability.md must show each file with the message the CLI prints today.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

struct Case {
  std::string file, problem, fragment;
  std::string format() const { return file.substr(0, file.find('/')); }
  std::string base() const { return file.substr(file.rfind('/') + 1); }
};

std::vector<Case> cases() {
  const auto text = read_file(repo_path("tests/malformed/expected.tsv"));
  REQUIRE(text);
  std::vector<Case> out;
  std::istringstream in(*text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t t1 = line.find('\t'), t2 = line.find('\t', t1 + 1);
    REQUIRE(t2 != std::string::npos);
    out.push_back({line.substr(0, t1), line.substr(t1 + 1, t2 - t1 - 1), line.substr(t2 + 1)});
  }
  return out;
}

std::string work_dir() {
  const std::string d = std::string(PT_BINARY_DIR) + "/malformed";
  std::filesystem::create_directories(d);
  return d;
}

// The scene the CLI is given: the file itself, or a scene that references it.
std::string scene_for(const Case& c) {
  const std::string abs = repo_path("tests/malformed/" + c.file);
  if (c.format() == "xml") return abs;
  // Image formats reach the loader as an environment map, every other one as a mesh
  // (a new mesh format, e.g. tests/malformed/gltf/, needs no change here).
  const std::string f = c.format();
  const bool image = f == "hdr" || f == "png" || f == "pfm" || f == "jpg" || f == "exr";
  const std::string ref = !image ? "<Objects><Mesh src=\"" + abs + "\"><Diffuse/></Mesh></Objects>\n"
                                 : "<Environment map=\"" + abs + "\"/>\n<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere></Objects>\n";
  const std::string path = work_dir() + "/wrap-" + c.base() + ".xml";
  std::ofstream(path) << "<SceneLevel>\n<Camera position=\"0 0 10\"/>\n" << ref << "</SceneLevel>\n";
  return path;
}

// The message names the broken file, then where in it: ":line:", ": byte N:", a pixel, or
// (glTF, whose parsed JSON has no lines) a JSON pointer ": /accessors/3:".
bool names_location(const std::string& msg, const std::string& base) {
  const std::string b = std::regex_replace(base, std::regex(R"([.\-])"), R"(\$&)");
  return std::regex_search(msg, std::regex(b + R"((:[0-9]+: |: byte [0-9]+: |' pixel \([0-9]+, [0-9]+\)|: (/[A-Za-z0-9_]+)+: ))"));
}

// Paths in messages, made independent of where the repository and build live.
std::string normalised(std::string msg) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{std::string(PT_BINARY_DIR) + "/", "<build>/"},
                                 {std::string(PT_SOURCE_DIR) + "/", ""}})
    for (size_t at = msg.find(from); at != std::string::npos; at = msg.find(from, at)) msg.replace(at, from.size(), to);
  return msg;
}

struct CliResult {
  int status = -1;  // exit code; -1: did not exit normally (a crash)
  std::string err;
};

CliResult run_cli(const std::string& scene) {
  const std::string cmd = std::string(PT_BINARY_DIR) + "/pathtracer render '" + scene + "' --spp 1 --size 8x8 --out '" +
                          work_dir() + "/never.png' 2>&1 >/dev/null";
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.err.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

}  // namespace

TEST_CASE("malformed inputs: the loader rejects every file naming file, location and problem", "[malformed]") {
  const std::vector<Case> all = cases();
  CHECK(all.size() >= 30);
  for (const Case& c : all) {
    INFO(c.file << " (" << c.problem << ")");
    std::string msg = "(loaded without error)";
    try {
      load_scene_file(scene_for(c));
    } catch (const InputError& e) {
      msg = e.what();
    }
    INFO("message: " << msg);
    CHECK(msg.find(c.fragment) != std::string::npos);
    CHECK(names_location(msg, c.base()));
  }
}

TEST_CASE("malformed inputs: the CLI exits 1 with one line naming file, location and problem", "[malformed][cli]") {
  std::string table;
  for (const Case& c : cases()) {
    INFO(c.file << " (" << c.problem << ")");
    const CliResult r = run_cli(scene_for(c));
    INFO("exit " << r.status << ", stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.rfind("pathtracer: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find(c.fragment) != std::string::npos);
    CHECK(names_location(r.err, c.base()));
    const std::string shown = normalised(r.err.substr(0, r.err.find('\n')));
    table += "| `" + c.file + "` | " + c.problem + " | `" + shown + "` |\n";
  }
  // The table in the docs is the CLI's output today, row for row.
  std::ofstream(work_dir() + "/table.md") << table;
  const auto docs = read_file(repo_path("docs/reliability.md"));
  REQUIRE(docs);
  std::istringstream rows(table);
  for (std::string row; std::getline(rows, row);) {
    INFO("docs/reliability.md lacks the row (regenerated table: <build>/malformed/table.md)\n" << row);
    CHECK(docs->find(row) != std::string::npos);
  }
}

TEST_CASE("malformed inputs: a scene file over 16 MiB is refused before parsing", "[malformed][cli]") {
  const std::string path = work_dir() + "/huge.xml";
  {
    std::ofstream out(path);
    out << "<SceneLevel><Camera position=\"0 0 10\"/><Objects>\n";
    const std::string sphere = "<Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere>\n";
    for (size_t n = 0; n * sphere.size() <= kMaxSceneBytes; ++n) out << sphere;
    out << "</Objects></SceneLevel>\n";
  }
  try {
    load_scene_file(path);
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("huge.xml: the scene file has ") == 0 + std::string(e.what()).find("huge.xml"));
    CHECK(std::string(e.what()).find("bytes (at most 16777216)") != std::string::npos);
  }
  const CliResult r = run_cli(path);
  CHECK(r.status == 1);
  CHECK(r.err.find("huge.xml: the scene file has ") != std::string::npos);
  std::filesystem::remove(path);
}
