#include "sbatch_script_model.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstring>

extern char** environ;

namespace taa::farm::testing {
namespace {

// sbatch overwrites these words with spaces wherever they stand in an #SBATCH line.
void blankHetjobWords(std::string& line) {
  for (const std::string word : {"hetjob", "packjob"}) {
    for (std::size_t at = 0; at + word.size() <= line.size(); ++at) {
      bool same = true;
      for (std::size_t i = 0; i < word.size() && same; ++i) {
        same = std::tolower(static_cast<unsigned char>(line[at + i])) == word[i];
      }
      if (same) line.replace(at, word.size(), std::string(word.size(), ' '));
    }
  }
}

// One #SBATCH line's words after the magic word, as sbatch's _get_argument splits them.
bool splitSbatchWords(std::string line, std::vector<std::string>& words, std::string& error) {
  blankHetjobWords(line);
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= line.size()) return true;
    if (line[i] == ':') {
      error = "a word starts with ':'";
      return false;
    }
    std::string word;
    bool escaped = false, quoted = false;
    char quote = 0;
    for (; i < line.size() && (quoted || !std::isspace(static_cast<unsigned char>(line[i]))); ++i) {
      const char c = line[i];
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
        continue;
      } else if (quoted) {
        if (c == quote) {
          quoted = false;
          continue;
        }
      } else if (c == '"' || c == '\'') {
        quoted = true;
        quote = c;
        continue;
      } else if (c == '#') {
        i = line.size();  // a comment to the end of the line
        break;
      }
      word += c;
    }
    if (quoted) {
      error = "unmatched quote";
      return false;
    }
    if (word.empty()) return true;  // sbatch's parser returns no word: the line ends there
    words.push_back(word);
  }
}

}  // namespace

ParsedScript parseBatchScript(const std::string& script) {
  ParsedScript parsed;
  std::size_t begin = 0;
  while (begin < script.size()) {
    std::size_t end = script.find('\n', begin);
    if (end == std::string::npos) end = script.size();
    const std::string line = script.substr(begin, end - begin);
    if (line.compare(0, 7, "#SBATCH") == 0) {
      if (!splitSbatchWords(line.substr(7), parsed.sbatchWords, parsed.error)) return parsed;
    } else if (const std::size_t text = line.find_first_not_of(" \t");
               text != std::string::npos && line[text] != '#') {
      parsed.body = script.substr(begin);  // sbatch reads no #SBATCH line after a command
      return parsed;
    }
    begin = end + 1;
  }
  return parsed;
}

std::optional<std::vector<std::string>> commandWordsBashRuns(const std::string& body) {
  int output[2];
  if (::pipe(output) != 0) return std::nullopt;
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, output[1], 1);
  posix_spawn_file_actions_addclose(&files, output[0]);
  posix_spawn_file_actions_addclose(&files, output[1]);
  // Outside POSIX mode, bash finds functions before builtins, exec included.
  const std::string command =
      "cd() { printf '%s\\0' cd \"$@\"; }\nexec() { printf '%s\\0' exec \"$@\"; }\n" + body;
  const char* argv[] = {"bash", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  const int failed = posix_spawnp(&pid, "bash", &files, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&files);
  ::close(output[1]);
  std::string printed;
  char buffer[4096];
  for (ssize_t n; !failed && (n = ::read(output[0], buffer, sizeof buffer)) > 0;) {
    printed.append(buffer, std::size_t(n));
  }
  ::close(output[0]);
  if (failed) return std::nullopt;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  std::vector<std::string> words;
  for (std::size_t start = 0, nul; (nul = printed.find('\0', start)) != std::string::npos;
       start = nul + 1) {
    words.push_back(printed.substr(start, nul - start));
  }
  return words;
}

}  // namespace taa::farm::testing
