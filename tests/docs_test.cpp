// The format documentation cannot drift: every ```xml block of docs/scene-format.md is
// a scene that must load (paths in it are relative to docs/).
#include <catch2/catch.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

TEST_CASE("every example in docs/scene-format.md loads", "[loader][docs]") {
  const std::string path = repo_path("docs/scene-format.md");
  const auto text = read_file(path);
  REQUIRE(text);
  int examples = 0;
  for (size_t at = text->find("```xml\n"); at != std::string::npos; at = text->find("```xml\n", at)) {
    const size_t begin = at + 7, end = text->find("```", begin);
    REQUIRE(end != std::string::npos);
    const std::string xml = text->substr(begin, end - begin);
    INFO("example " << examples + 1 << ":\n" << xml);
    try {
      load_scene_text(xml, path);
    } catch (const InputError& e) {
      FAIL(e.what());
    }
    ++examples;
    at = end + 3;
  }
  CHECK(examples >= 7);  // one per section
}
