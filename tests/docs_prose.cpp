// The prose of README.md and docs/*.md reads as a reference: sentences short, no "seed", no
// measurement outside the generated performance page.
// Prose is what lies outside fenced blocks, HTML comments, tables and headings. A sentence ends at
// '.', '?' or '!' before whitespace; a list item counts as at least one sentence. The median
// sentence holds at most 20 words, none more than 45. A timing (ns, us, ms, minutes), a memory size
// (MB, GB) or a ratio (2.5x) outside docs/performance.md fails, as does the word "seed".
// Usage: docs_prose SOURCE_DIR. Each failure is printed with its file.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
struct sentence {
  std::string file, text;
  std::size_t words;
};

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::size_t count_words(const std::string& s) {
  std::istringstream in(s);
  std::size_t n = 0;
  for (std::string w; in >> w;) ++n;
  return n;
}
// The prose units of a page: paragraphs and list items, joined into one line each.
std::vector<std::string> units(const std::string& text) {
  std::vector<std::string> out;
  std::string para;
  const auto flush = [&] {
    if (!para.empty()) out.push_back(para);
    para.clear();
  };
  std::istringstream in(text);
  bool fenced = false, comment = false;
  const std::regex item(R"(^\s*([-*]|\d+\.)\s+)");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      flush();
      continue;
    }
    if (fenced) continue;
    if (comment || line.find("<!--") != std::string::npos) {
      comment = line.find("-->") == std::string::npos;
      flush();
      continue;
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '|' || line[first] == '#') {
      flush();
      continue;
    }
    if (std::regex_search(line, item)) {
      flush();
      line = std::regex_replace(line, item, "");
    }
    para += (para.empty() ? "" : " ") + line.substr(line.find_first_not_of(" \t"));
  }
  flush();
  return out;
}
std::vector<std::string> split_sentences(const std::string& unit) {
  std::vector<std::string> out;
  std::string s;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    s += unit[i];
    const bool end = (unit[i] == '.' || unit[i] == '?' || unit[i] == '!') &&
                     (i + 1 == unit.size() || std::isspace(static_cast<unsigned char>(unit[i + 1])));
    if (end) out.push_back(s), s.clear();
  }
  if (count_words(s) > 0) out.push_back(s);
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: docs_prose SOURCE_DIR\n");
    return 2;
  }
  const fs::path root = argv[1];
  std::vector<fs::path> pages{root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  const std::regex measured(R"(\d(\.\d+)? ?(ns|us|ms|minutes|MB|GB)\b|\d(\.\d+)?x\b)");
  const std::regex seed(R"(\bseed\b)", std::regex::icase);
  std::vector<sentence> all;
  int failures = 0;
  for (const auto& page : pages) {
    const std::string name = fs::relative(page, root).string();
    if (name == "docs/performance.md") continue;  // generated: its figures live there
    for (const auto& u : units(read(page)))
      for (const auto& s : split_sentences(u)) {
        const std::size_t w = count_words(s);
        all.push_back({name, s, w});
        if (w > 45) std::printf("%s: a sentence of %zu words: %s\n", name.c_str(), w, s.c_str()), ++failures;
        if (std::regex_search(s, measured))
          std::printf("%s: a measurement in prose: %s\n", name.c_str(), s.c_str()), ++failures;
        if (std::regex_search(s, seed))
          std::printf("%s: \"seed\": %s\n", name.c_str(), s.c_str()), ++failures;
      }
  }
  std::vector<std::size_t> words;
  for (const auto& s : all) words.push_back(s.words);
  std::sort(words.begin(), words.end());
  const double median = words.empty()      ? 0.0
                        : words.size() % 2 ? double(words[words.size() / 2])
                                           : (words[words.size() / 2 - 1] + words[words.size() / 2]) / 2.0;
  std::printf("%zu sentences, median %.1f words, longest %zu\n", words.size(), median,
              words.empty() ? std::size_t(0) : words.back());
  if (median > 20) std::printf("the median sentence holds more than 20 words\n"), ++failures;
  return failures == 0 ? 0 : 1;
}
