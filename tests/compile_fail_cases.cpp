// Checks the compile-fail cases of one source (`// case NAME: RE1 && RE2 ...`, the misuse under
// `#ifdef KANE_CASE_NAME`). One compile defines KANE_A_CASE and the macros of all its cases; each error is
// given to the case whose region holds the source line it was required from (g++: the last such line up
// to the error; clang++: the first from the error on). A region is a misuse block, or a part that
// KANE_A_CASE leaves out but for one case. A case passes when the compile fails, its
// first error line matches every RE and the lines of its errors stay under MAX_BYTES. A case that finds
// no error of its own, or another line first, is compiled alone with -Wfatal-errors and checked on that
// diagnostic: a misuse whose instantiation another case made first reports nothing in the shared compile.
// Usage: kane_compile_fail_cases gnu|clang all|rules MAX_BYTES SOURCE CXX FLAGS...
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {
struct kase {
  std::string name;
  std::vector<std::regex> regexes;
  std::vector<std::string> patterns;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The output (stdout and stderr) and the exit status of a command.
std::string run(const std::string& command, int& status) {
  std::string out;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[4096];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  status = pclose(p);
  return out;
}

bool matches(const kase& c, const std::string& line) {
  for (const auto& r : c.regexes)
    if (!std::regex_search(line, r)) return false;
  return true;
}

// The case alone (-Wfatal-errors): its first error line and its whole diagnostic.
bool alone(const std::string& command, const kase& c, std::size_t max_bytes, std::string& why,
           std::size_t& bytes) {
  int status = 0;
  const std::string out = run(command + " -Wfatal-errors -DKANE_CASE_" + c.name, status);
  bytes = out.size();
  std::smatch m;
  static const std::regex first("[^\n]*error: [^\n]*");
  if (status == 0) return why = "compiled, but it must not", false;
  if (!std::regex_search(out, m, first)) return why = "failed without an error line:\n" + out, false;
  if (!matches(c, m.str())) return why = "alone, its first error line does not match:\n" + m.str(), false;
  if (out.size() > max_bytes)
    return why = "alone, a diagnostic of " + std::to_string(out.size()) + " bytes", false;
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s gnu|clang all|rules MAX_BYTES SOURCE CXX FLAGS...\n", argv[0]);
    return 2;
  }
  const bool gnu = std::string(argv[1]) == "gnu", rules_only = std::string(argv[2]) == "rules";
  const std::size_t max_bytes = std::stoul(argv[3]);
  const std::string source = argv[4];
  std::string command = quoted(argv[5]);
  for (int i = 6; i < argc; ++i) command += " " + quoted(argv[i]);
  command += " -fsyntax-only -DKANE_A_CASE " + quoted(source);

  std::ifstream in(source);
  std::stringstream text;
  text << in.rdbuf();
  const auto src = lines_of(text.str());
  std::vector<kase> cases;
  static const std::regex case_line("^// case ([a-z_0-9]+): (.*)$");
  for (const auto& l : src) {
    std::smatch m;
    if (!std::regex_match(l, m, case_line)) continue;
    kase c{m[1], {}, {}};
    std::string rest = m[2];
    for (std::size_t at; !rest.empty(); rest = at == std::string::npos ? "" : rest.substr(at + 4)) {
      at = rest.find(" && ");
      c.patterns.push_back(rest.substr(0, at));
      c.regexes.emplace_back(c.patterns.back());
    }
    if (!rules_only || c.patterns.front().rfind("kane: ", 0) != 0) cases.push_back(c);
  }

  // owner[line] = the case whose region holds the 1-based line: a misuse block (`#if`, `#ifdef` or
  // `#elif` naming one case) or, where no block is, a part left out under KANE_A_CASE but for one case.
  std::map<std::size_t, std::string> owner;
  static const std::regex macro("KANE_CASE_([a-z_0-9]+)");
  static const std::regex opens("^\\s*#\\s*if"), splits("^\\s*#\\s*(else|elif)"), ends("^\\s*#\\s*endif");
  for (const bool helpers : {true, false}) {
    for (std::size_t i = 0; i < src.size(); ++i) {
      if (!std::regex_search(src[i], opens) && !std::regex_search(src[i], splits)) continue;
      std::string l = src[i];
      std::size_t j = i;
      while (!src[j].empty() && src[j].back() == '\\' && j + 1 < src.size()) l += src[++j];
      if ((l.find("KANE_A_CASE") != std::string::npos) != helpers) continue;
      std::vector<std::string> named;
      for (std::sregex_iterator m(l.begin(), l.end(), macro), e; m != e; ++m) named.push_back((*m)[1]);
      if (named.size() != 1) continue;
      for (std::size_t depth = 0; ++j < src.size();) {
        if (std::regex_search(src[j], opens))
          ++depth;
        else if (std::regex_search(src[j], ends) && depth-- == 0)
          break;
        else if (depth == 0 && std::regex_search(src[j], splits))
          break;
        owner[j + 1] = named[0];
      }
    }
  }

  std::string all = command;
  for (const auto& c : cases) all += " -DKANE_CASE_" + c.name;
  int status = 0;
  const auto out = lines_of(run(all + (gnu ? " -fmax-errors=0" : " -ferror-limit=0"), status));
  const std::regex ref(std::regex_replace(source, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                       ":([0-9]+):");
  auto case_at = [&](std::size_t k) -> std::string {
    std::smatch m;
    if (std::regex_search(out[k], m, ref)) {
      const auto it = owner.find(std::stoul(m[1]));
      if (it != owner.end()) return it->second;
    }
    return {};
  };
  std::vector<std::size_t> errors;
  for (std::size_t k = 0; k < out.size(); ++k)
    if (out[k].find("error: ") != std::string::npos) errors.push_back(k);
  std::map<std::string, std::string> first;
  std::map<std::string, std::size_t> bytes;
  for (std::size_t e = 0; e < errors.size(); ++e) {
    // g++ prints the instantiation context before the error, clang++ after it.
    const std::size_t from = gnu ? (e ? errors[e - 1] + 1 : 0) : errors[e];
    const std::size_t to = gnu ? errors[e] + 1 : (e + 1 < errors.size() ? errors[e + 1] : out.size());
    std::string who = case_at(errors[e]);
    for (std::size_t k = from; who.empty() && k < to; ++k) {
      const std::size_t at = gnu ? to - 1 - (k - from) : k;
      who = case_at(at);
    }
    if (who.empty()) continue;
    if (!first.count(who)) first[who] = out[errors[e]];
    for (std::size_t k = from; k < to; ++k) bytes[who] += out[k].size() + 1;
  }

  int failed = 0;
  for (const auto& c : cases) {
    std::string why;
    const auto it = first.find(c.name);
    const bool shared =
        status != 0 && it != first.end() && matches(c, it->second) && bytes[c.name] <= max_bytes;
    if (shared) {
      std::printf("case %s: diagnostic of %zu bytes\n", c.name.c_str(), bytes[c.name]);
    } else if (std::size_t n = 0; alone(command, c, max_bytes, why, n)) {
      std::printf("case %s: diagnostic of %zu bytes, compiled alone\n", c.name.c_str(), n);
    } else {
      std::printf("case %s FAILED: %s\n", c.name.c_str(), why.c_str());
      ++failed;
    }
  }
  std::printf("%zu cases of %s, %d failed\n", cases.size(), source.c_str(), failed);
  return failed ? 1 : 0;
}
