// docs/cli.md against the command line itself: every option of every subcommand has a row in its
// command's table (a row whose first cell names `--flag`, alone or beside others), and where the
// option has a default, the row's default cell shows it as `--help` does. The defaults come from
// the library's settings (amrstream/settings.hpp) or the request structs; the docs are checked,
// not copied.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "amrstream/mpi_world.hpp"
#include "amrstream/settings.hpp"
#include "commands.hpp"

namespace {

std::string readDocs() {
  std::ifstream in(AMRSTREAM_CLI_DOCS);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The table rows of each command's section: "## `amrstream NAME ...`" up to the next "## ".
std::map<std::string, std::vector<std::string>> rowsByCommand(const std::string& docs) {
  std::map<std::string, std::vector<std::string>> rows;
  std::istringstream lines(docs);
  std::string command = "(common)";
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("## `amrstream ")) {
      const std::string rest = line.substr(std::string("## `amrstream ").size());
      command = rest.substr(0, rest.find_first_of(" `"));
    } else if (line.starts_with("| `")) {
      rows[command].push_back(line);
    }
  }
  return rows;
}

// The cells of a table row, split at unescaped bars.
std::vector<std::string> cellsOf(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return cells;
}

// The row whose first cell names `flag` (as "`--flag" followed by a space, a backtick or a comma).
const std::string* rowNaming(const std::vector<std::string>& rows, const std::string& flag) {
  for (const std::string& row : rows) {
    const std::vector<std::string> cells = cellsOf(row);
    if (cells.empty()) continue;
    for (std::size_t at = cells[0].find("`" + flag); at != std::string::npos;
         at = cells[0].find("`" + flag, at + 1)) {
      const char next =
          at + flag.size() + 1 < cells[0].size() ? cells[0][at + flag.size() + 1] : ' ';
      if (next == ' ' || next == '`' || next == ',') return &row;
    }
  }
  return nullptr;
}

// The commands whose sections take another's options without repeating them ("Traces like
// `trace`", "Takes the options of `render`", "with the seeding options of `trace`").
const std::map<std::string, std::string> kTakesOptionsOf{
    {"render", "trace"}, {"view", "render"}, {"pathlines", "trace"}, {"resample", "trace"}};

// The row documenting `flag` for `command`: its own table's, else that of the command it takes
// its options from, and a row that says "as for `X`" without a default stands for X's row.
const std::string* documentingRow(const std::map<std::string, std::vector<std::string>>& rows,
                                  std::string command, const std::string& flag) {
  while (true) {
    const auto found = rows.find(command);
    const std::string* row = found == rows.end() ? nullptr : rowNaming(found->second, flag);
    if (row) {
      const std::vector<std::string> cells = cellsOf(*row);
      const bool deferred = cells.size() > 2 &&
                            cells[1].find_first_not_of(' ') == std::string::npos &&
                            cells[2].find("as for `trace`") != std::string::npos;
      if (!deferred || command == "trace") return row;
      command = "trace";
      continue;
    }
    const auto parent = kTakesOptionsOf.find(command);
    if (parent == kTakesOptionsOf.end()) break;
    command = parent->second;
  }
  // The builtin datasets' sizes are documented once, above the commands.
  return rowNaming(rows.at("(common)"), flag);
}

// "[128]" (a list's default as CLI11 shows it) -> "128".
std::string withoutBrackets(std::string text) {
  if (text.size() >= 2 && text.front() == '[' && text.back() == ']')
    text = text.substr(1, text.size() - 2);
  return text;
}

TEST(CliDocs, EveryOptionHasARowWithItsDefault) {
  const std::string docs = readDocs();
  ASSERT_FALSE(docs.empty()) << AMRSTREAM_CLI_DOCS;
  const auto rows = rowsByCommand(docs);
  const amrstream::MpiWorld world;
  CLI::App app;
  amrstream::cli::addCommands(app, world, "amrstream");
  std::size_t checked = 0;
  for (const CLI::App* command : app.get_subcommands({})) {
    const std::string name = command->get_name();
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_lnames().empty() || option->get_lnames()[0] == "help") continue;
      const std::string flag = "--" + option->get_lnames()[0];
      const std::string* row = documentingRow(rows, name, flag);
      EXPECT_NE(row, nullptr) << "docs/cli.md: no row for " << name << " " << flag;
      const std::string shown = withoutBrackets(option->get_default_str());
      if (!row || shown.empty() || option->get_expected_min() == 0) continue;
      const std::vector<std::string> cells = cellsOf(*row);
      ASSERT_GE(cells.size(), 2u) << *row;
      EXPECT_THAT(cells[1], ::testing::HasSubstr(shown))
          << "docs/cli.md: " << name << " " << flag << "'s default is " << shown;
      ++checked;
    }
  }
  EXPECT_GT(checked, 60u);
}

}  // namespace
