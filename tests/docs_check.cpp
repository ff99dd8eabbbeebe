// Every fenced block of README.md and docs/*.md comes from a file the suite builds or runs, named on
// the line before its opening fence:
//   <!-- from PATH -->          each line of the block (trimmed; blank lines and "..." skipped) is a
//                               line of PATH (trimmed), in the same order;
//   <!-- output of EXAMPLE -->  the block is what BIN_DIR/EXAMPLE prints.
// Usage: docs_check SOURCE_DIR BIN_DIR. A block without such a line, a line not found, or other
// output is reported and fails.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
std::vector<std::string> read_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
std::string run(const fs::path& program, int& status) {
  std::string out;
  FILE* p = popen(program.c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  status = pclose(p);
  return out;
}
bool starts(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: docs_check SOURCE_DIR BIN_DIR\n";
    return 2;
  }
  const fs::path source = argv[1], bin = argv[2];
  std::vector<fs::path> pages{source / "README.md"};
  for (const auto& e : fs::directory_iterator(source / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  std::sort(pages.begin() + 1, pages.end());
  int blocks = 0, failures = 0;
  const auto fail = [&](const fs::path& page, std::size_t line, const std::string& what) {
    std::cerr << fs::relative(page, source).string() << ":" << line << ": " << what << "\n";
    ++failures;
  };
  for (const auto& page : pages) {
    const auto lines = read_lines(page);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!starts(lines[i], "```")) continue;
      std::size_t end = i + 1;
      while (end < lines.size() && lines[end] != "```") ++end;
      const std::vector<std::string> block(lines.begin() + long(i) + 1, lines.begin() + long(end));
      const std::string tag = i > 0 ? lines[i - 1] : "";
      ++blocks;
      const std::string from = "<!-- from ", output = "<!-- output of ", close = " -->";
      if (starts(tag, from) && tag.size() > from.size() + close.size()) {
        const fs::path file = source / tag.substr(from.size(), tag.size() - from.size() - close.size());
        if (!fs::exists(file)) {
          fail(page, i + 1, file.string() + " does not exist");
        } else {
          std::vector<std::string> have;
          for (const auto& l : read_lines(file)) have.push_back(trim(l));
          std::size_t at = 0;
          for (const auto& l : block) {
            const std::string want = trim(l);
            if (want.empty() || want == "..." || want == "// ...") continue;
            while (at < have.size() && have[at] != want) ++at;
            if (at == have.size()) {
              fail(page, i + 1, "not in " + fs::relative(file, source).string() + " (in order): " + want);
              break;
            }
            ++at;
          }
        }
      } else if (starts(tag, output) && tag.size() > output.size() + close.size()) {
        const std::string name = tag.substr(output.size(), tag.size() - output.size() - close.size());
        int status = 0;
        const std::string printed = run(bin / name, status);
        std::string expected;
        for (const auto& l : block) expected += l + "\n";
        if (status != 0 || printed != expected) fail(page, i + 1, name + " printed:\n" + printed);
      } else {
        fail(page, i + 1, "a block without <!-- from PATH --> or <!-- output of EXAMPLE --> before it");
      }
      i = end;
    }
  }
  std::cout << blocks << " blocks in " << pages.size() << " pages, " << failures << " not from the suite\n";
  return failures == 0 ? 0 : 1;
}
