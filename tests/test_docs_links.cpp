// README.md and docs/*.md are the front door and the manual: every relative link and image in them
// must resolve, and every #anchor must name a heading of its page (GitHub's slugs), so that moving a
// file or renaming a section cannot leave a dead link behind.
#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;

// GitHub's anchor for a heading: lower case, punctuation dropped (but '-' and '_'), spaces to '-'.
std::string slug(const std::string& heading) {
  std::string out;
  for (const unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) out += static_cast<char>(std::tolower(c));
    else if (c == ' ') out += '-';
  }
  return out;
}

std::set<std::string> anchors_of(const std::string& markdown) {
  std::set<std::string> out;
  const std::regex heading(R"(^#+ +(.+?) *$)");
  bool in_code = false;
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    std::smatch m;
    if (!in_code && std::regex_match(line, m, heading)) out.insert(slug(m[1]));
  }
  return out;
}

struct Link {
  std::string page, target;
};

std::vector<Link> links_of(const fs::path& page, const std::string& markdown) {
  std::vector<Link> out;
  // [text](target) and ![alt](target), outside code blocks and code spans.
  const std::regex link(R"(\]\(([^)\s]+)\))");
  bool in_code = false;
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (in_code) continue;
    const std::string text = std::regex_replace(line, std::regex("`[^`]*`"), "");
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it)
      out.push_back({page.string(), (*it)[1]});
  }
  return out;
}

std::vector<fs::path> pages() {
  std::vector<fs::path> out{rt::test::source_path("README.md")};
  for (const auto& entry : fs::directory_iterator(rt::test::source_path("docs")))
    if (entry.path().extension() == ".md") out.push_back(entry.path());
  return out;
}

}  // namespace

TEST_CASE("Every relative link and image in README.md and docs/*.md resolves", "[docs]") {
  size_t checked = 0;
  std::vector<std::string> dead;
  for (const fs::path& page : pages()) {
    const std::string text = rt::test::read_file(page.string());
    for (const Link& l : links_of(page, text)) {
      if (l.target.rfind("http://", 0) == 0 || l.target.rfind("https://", 0) == 0 || l.target.rfind("mailto:", 0) == 0)
        continue;
      ++checked;
      const size_t hash = l.target.find('#');
      const std::string file = l.target.substr(0, hash);
      const std::string anchor = hash == std::string::npos ? "" : l.target.substr(hash + 1);
      const fs::path resolved = file.empty() ? page : page.parent_path() / file;
      if (!fs::exists(resolved)) {
        dead.push_back(page.filename().string() + ": " + l.target + " (no such file)");
        continue;
      }
      if (!anchor.empty() && !anchors_of(rt::test::read_file(resolved.string())).count(anchor))
        dead.push_back(page.filename().string() + ": " + l.target + " (no such heading)");
    }
  }
  INFO("links checked: " << checked);
  CHECK(pages().size() >= 7);
  CHECK(checked > 40);
  for (const std::string& d : dead) UNSCOPED_INFO(d);
  CHECK(dead.empty());
}

TEST_CASE("The link check reads links, images and anchors as GitHub does", "[docs]") {
  CHECK(slug("Code map") == "code-map");
  CHECK(slug("Textures, bump and normal maps") == "textures-bump-and-normal-maps");
  const auto links =
      links_of("docs/x.md", "see [a](b.md#c) and ![i](images/p.png)\n`[not](a link)`\n```\n[no](x)\n```\n");
  REQUIRE(links.size() == 2);
  CHECK(links[0].target == "b.md#c");
  CHECK(links[1].target == "images/p.png");
  CHECK(anchors_of("# Title\n```\n# not a heading\n```\n## Sub part\n") == std::set<std::string>{"title", "sub-part"});
}
