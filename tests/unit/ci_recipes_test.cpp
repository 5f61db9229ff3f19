// The CI recipes users copy (docs/ci/github-actions.yml, docs/ci/gitlab-ci.yml, the Dockerfile, the
// commands in docs/ci.md) run commands of this version: every shadelab command line parses with this
// build's options, every -DSHADELAB_… they give is an option of this build, every file of this
// repository they name exists, every package list they install from exists. A renamed flag or
// option, or a moved file, fails here instead of in a user's pipeline.
#include "options/options.hpp"
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = SHADELAB_SOURCE_DIR;

// (core's reader: it throws, and the test fails, for a file that is not there)
std::string readText(const fs::path& path) { return readTextFile(path.string(), 1u << 20); }

// The file's commands, one per entry: what follows `run:` (a line, or the lines of its `|` block),
// a `- ` item of a GitLab script, a Dockerfile RUN, or a line of a ```sh block in Markdown; lines
// ending in '\' joined to the next; then split at `&&`, `;` and `|`.
std::vector<std::string> commandsOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        while (!line.empty() && line.back() == '\\') {
            std::string next;
            if (!std::getline(in, next)) break;
            line.pop_back();
            line += " " + next;
        }
        lines.push_back(line);
    }
    std::vector<std::string> commands;
    const std::regex prefix(R"(^\s*(-\s+)?(run:\s*|RUN\s+|\$\s+)?)");
    for (const std::string& line : lines) {
        const std::string body = std::regex_replace(line, prefix, "", std::regex_constants::format_first_only);
        std::size_t start = 0;
        for (std::size_t i = 0; i <= body.size(); ++i) {
            const bool split = i == body.size() || body[i] == ';' || body[i] == '|' ||
                               (body[i] == '&' && i + 1 < body.size() && body[i + 1] == '&');
            if (!split) continue;
            std::string command = body.substr(start, i - start);
            command.erase(0, command.find_first_not_of(" \t"));
            if (!command.empty()) commands.push_back(command);
            start = i + (i < body.size() && body[i] == '&' ? 2 : 1);
            if (i < body.size() && body[i] == '&') ++i;
        }
    }
    return commands;
}

// Shell words, with "…" and '…' quoting (no expansions: the recipes quote their variables).
std::vector<std::string> wordsOf(const std::string& command) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (char c : command) {
        if (quote) {
            if (c == quote) quote = 0;
            else word += c;
        } else if (c == '"' || c == '\'') {
            quote = c;
            inWord = true;
        } else if (c == ' ' || c == '\t') {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) words.push_back(word);
    return words;
}

// A path of this repository as a recipe names it: /opt/shadelab/X (the GitHub and GitLab clones),
// /src/X (the Dockerfile's copy), or a plain relative path.
fs::path repositoryPath(std::string path) {
    for (const std::string root : {"/opt/shadelab/", "/src/"})
        if (path.rfind(root, 0) == 0) return kSource / path.substr(root.size());
    return kSource / path;
}

struct Checked {
    int shadelab = 0, cmakeOptions = 0, files = 0;
};

// A word with the variables the recipes pass to shadelab replaced by values they take: the CI's own
// (GitHub's matrix, GitLab's parallel jobs) and the loop of docs/ci.md's measurements.
std::string withCiValues(std::string word) {
    for (const auto& [variable, value] : {std::pair<std::string, std::string>{"${{ matrix.shard }}", "2"},
                                          {"${{ strategy.job-total }}", "4"},
                                          {"$CI_NODE_INDEX", "2"},
                                          {"$CI_NODE_TOTAL", "4"},
                                          {"$((ke + 1))", "33"},
                                          {"$ke", "32"},
                                          {"$size", "320x240"}})
        for (std::size_t at = word.find(variable); at != std::string::npos; at = word.find(variable))
            word.replace(at, variable.size(), value);
    return word;
}

void checkCommand(const std::string& where, const std::vector<std::string>& words, Checked& checked) {
    if (words.empty()) return;
    if (words[0] == "shadelab") {
        std::vector<std::string> args;
        for (auto w = words.begin() + 1; w != words.end(); ++w) args.push_back(withCiValues(*w));
        try {
            parseOptions(args);
        } catch (const InputError& e) {
            ADD_FAILURE() << where << ": `shadelab`'s options do not parse in this version: " << e.what();
        }
        ++checked.shadelab;
    } else if (words[0] == "cmake") {
        const std::string cmakeText = readText(kSource / "CMakeLists.txt") + readText(kSource / "cmake" / "ShadelabParts.cmake");
        for (const std::string& w : words) {
            if (w.rfind("-DSHADELAB_", 0) != 0) continue;
            const std::string name = w.substr(2, w.find('=') - 2);
            EXPECT_TRUE(std::regex_search(cmakeText, std::regex("\\b" + name + "\\b"))) << where << ": no CMake option " << name;
            ++checked.cmakeOptions;
        }
    } else if (words[0] == "bash") {
        for (std::size_t i = 1; i < words.size(); ++i) {
            EXPECT_TRUE(fs::is_regular_file(repositoryPath(words[i]))) << where << ": no file " << words[i];
            ++checked.files;
        }
    } else if (words[0] == "COPY" && words.size() >= 3 && words[1].rfind("--", 0) != 0) {
        for (std::size_t i = 1; i + 1 < words.size(); ++i) {
            EXPECT_TRUE(fs::exists(kSource / words[i])) << where << ": COPY of a missing " << words[i];
            ++checked.files;
        }
    }
}

// Markdown: the lines of its ``` blocks alone (prose may begin a line with "shadelab").
std::string codeBlocksOf(const std::string& markdown) {
    std::istringstream in(markdown);
    std::string code;
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) inside = !inside;
        else if (inside) code += line + "\n";
    }
    return code;
}

Checked checkRecipe(const fs::path& relative) {
    Checked checked;
    std::string text = readText(kSource / relative);
    if (relative.extension() == ".md") text = codeBlocksOf(text);
    for (const std::string& command : commandsOf(text))
        checkCommand(relative.string() + ": " + command, wordsOf(command), checked);
    return checked;
}

TEST(CiRecipes, GitHubWorkflowRunsCommandsOfThisVersion) {
    const Checked c = checkRecipe("docs/ci/github-actions.yml");
    EXPECT_EQ(c.shadelab, 1);
    EXPECT_GE(c.cmakeOptions, 2);
    EXPECT_EQ(c.files, 2);  // install-deps.sh and its package list
}

TEST(CiRecipes, GitLabJobRunsCommandsOfThisVersion) {
    const Checked c = checkRecipe("docs/ci/gitlab-ci.yml");
    EXPECT_EQ(c.shadelab, 1);
    EXPECT_GE(c.cmakeOptions, 2);
    EXPECT_EQ(c.files, 2);
}

// Issue 32: the same split over parallel jobs (--shard K/N from the CI's job number).
TEST(CiRecipes, ShardedRecipesRunCommandsOfThisVersion) {
    for (const char* recipe : {"docs/ci/github-actions-sharded.yml", "docs/ci/gitlab-ci-parallel.yml"}) {
        const Checked c = checkRecipe(recipe);
        EXPECT_EQ(c.shadelab, 1) << recipe;
        EXPECT_GE(c.cmakeOptions, 2) << recipe;
        EXPECT_EQ(c.files, 2) << recipe;
    }
    const std::string github = readText(kSource / "docs/ci/github-actions-sharded.yml");
    EXPECT_NE(github.find("--shard \"${{ matrix.shard }}/${{ strategy.job-total }}\""), std::string::npos);
    EXPECT_NE(readText(kSource / "docs/ci/gitlab-ci-parallel.yml").find("--shard \"$CI_NODE_INDEX/$CI_NODE_TOTAL\""),
              std::string::npos);
}

// Issue 32: Mesa's shader cache is inside the project in both recipes (GitLab caches nothing else).
TEST(CiRecipes, MesaShaderCacheIsInsideTheProject) {
    for (const char* recipe : {"docs/ci/github-actions.yml", "docs/ci/gitlab-ci.yml", "docs/ci/github-actions-sharded.yml",
                               "docs/ci/gitlab-ci-parallel.yml"}) {
        const std::string text = readText(kSource / recipe);
        EXPECT_TRUE(text.find("MESA_SHADER_CACHE_DIR=$GITHUB_WORKSPACE/.mesa-shader-cache") != std::string::npos ||
                    text.find("MESA_SHADER_CACHE_DIR: \"$CI_PROJECT_DIR/.mesa-shader-cache\"") != std::string::npos)
            << recipe;
        EXPECT_NE(text.find(".mesa-shader-cache"), text.rfind(".mesa-shader-cache")) << recipe << ": set and cached";
    }
}

TEST(CiRecipes, DockerfileBuildsWithThisVersion) {
    const Checked c = checkRecipe("Dockerfile");
    EXPECT_GE(c.cmakeOptions, 2);
    EXPECT_EQ(c.files, 5);  // COPY of install-deps.sh, the list and the checkout; bash of the first two
}

TEST(CiRecipes, TheGuidesCommandsParse) {
    const Checked c = checkRecipe("docs/ci.md");
    EXPECT_GE(c.shadelab, 4);
}

// The checker itself: a flag this version does not have, an option CMake does not define and a file
// that does not exist are each caught.
TEST(CiRecipes, TheCheckerCatchesWhatIsNotThere) {
    static Checked c;  // (EXPECT_NONFATAL_FAILURE's statement cannot use a local)
    EXPECT_NONFATAL_FAILURE(checkCommand("x", wordsOf("shadelab --test s --no-such-flag"), c), "do not parse");
    EXPECT_NONFATAL_FAILURE(checkCommand("x", wordsOf("cmake -S . -DSHADELAB_NO_SUCH_PART=OFF"), c), "no CMake option");
    EXPECT_NONFATAL_FAILURE(checkCommand("x", wordsOf("bash /opt/shadelab/third_party/nothing.sh"), c), "no file");
    EXPECT_EQ(commandsOf("run: a && b | c; d"), (std::vector<std::string>{"a ", "b ", "c", "d"}));
    EXPECT_EQ(wordsOf(R"(git clone "$A" 'b c')"), (std::vector<std::string>{"git", "clone", "$A", "b c"}));
}

}  // namespace
}  // namespace shadelab
