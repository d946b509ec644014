// The helpers every tool shares: the hash of cache keys, the cache directory, the atomic write,
// the escaping that keeps messages on one line.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "files.hpp"
#include "hash.hpp"
#include "text.hpp"
#include "test_support.hpp"

using namespace fpstereo;
namespace fs = std::filesystem;

namespace {

// Sets (or, with nullopt, unsets) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = test::scratch_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("fnv1a64 is the standard 64-bit FNV-1a", "[tools]") {
  // The reference vectors of the FNV specification.
  CHECK(fnv1a64("") == 0xcbf29ce484222325ull);
  CHECK(fnv1a64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a64("foobar") == 0x85944171f73967e8ull);
  CHECK(fnv1a64(std::string("a\0b", 3)) != fnv1a64("ab"));
}

TEST_CASE("cache_dir follows the XDG base directory rules", "[tools]") {
  const ScopedEnv home("HOME", "/home/someone");
  SECTION("an absolute XDG_CACHE_HOME") {
    const ScopedEnv xdg("XDG_CACHE_HOME", "/var/cache/me");
    CHECK(cache_dir("dse") == fs::path("/var/cache/me/fpstereo/dse"));
    CHECK(cache_dir_rule("dse") == "$XDG_CACHE_HOME/fpstereo/dse or ~/.cache/fpstereo/dse");
  }
  SECTION("a relative XDG_CACHE_HOME is ignored") {
    const ScopedEnv xdg("XDG_CACHE_HOME", "relative/cache");
    CHECK(cache_dir("dse") == fs::path("/home/someone/.cache/fpstereo/dse"));
  }
  SECTION("an empty or missing XDG_CACHE_HOME") {
    const ScopedEnv xdg("XDG_CACHE_HOME", "");
    CHECK(cache_dir("synth") == fs::path("/home/someone/.cache/fpstereo/synth"));
    const ScopedEnv no_xdg("XDG_CACHE_HOME", std::nullopt);
    CHECK(cache_dir("synth") == fs::path("/home/someone/.cache/fpstereo/synth"));
  }
  SECTION("neither is set") {
    const ScopedEnv xdg("XDG_CACHE_HOME", std::nullopt);
    const ScopedEnv no_home("HOME", std::nullopt);
    CHECK_THROWS_WITH(cache_dir("dse"), "no cache directory: HOME is not set; pass --cache DIR");
  }
}

TEST_CASE("write_file_atomically replaces the file whole and leaves nothing else", "[tools]") {
  const fs::path dir = fresh_dir("fpstereo_test_atomic");
  const fs::path path = dir / "record.txt";
  write_file_atomically(path, "first\n");
  write_file_atomically(path, std::string("second\0with a NUL\n", 18));
  CHECK(contents(path) == std::string("second\0with a NUL\n", 18));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0644);

  CHECK_THROWS_WITH(write_file_atomically(dir / "missing" / "x.txt", "x"),
                    "cannot write '" + (dir / "missing" / "x.txt").string() + "': no such directory '" +
                        (dir / "missing").string() + "'");
  fs::remove_all(dir);
}

TEST_CASE("OutputSet refuses an output that is an input or another output, before any work", "[tools]") {
  const fs::path dir = fresh_dir("fpstereo_test_alias");
  std::ofstream(dir / "in.png") << "input";
  fs::create_symlink(dir / "in.png", dir / "link.png");
  OutputSet outputs;
  outputs.add_input(dir / "in.png", "left image");
  outputs.add_input(dir / "in.png", "right image");  // one file read twice is fine
  CHECK_THROWS_WITH(outputs.add_file(dir / "." / "in.png", "-o"),
                    Catch::Contains("is the same file as left image"));
  CHECK_THROWS_WITH(outputs.add_file(dir / "link.png", "-o"), Catch::Contains("is the same file as left image"));
  outputs.add_file(dir / "new.png", "-o");
  CHECK_THROWS_WITH(outputs.add_file(dir / "sub" / ".." / "new.png", "--pfm"),
                    Catch::Contains("is the same file as -o"));
  CHECK_THROWS_WITH(outputs.add_directory(dir, "-o directory"), Catch::Contains("lies inside -o directory"));
  CHECK_THROWS_WITH(outputs.add_file("", "--html"), "--html: an empty file name");
  CHECK_NOTHROW(outputs.add_file("/dev/null", "--colour"));  // a device replaces nothing: it may repeat
  CHECK_NOTHROW(outputs.add_file("/dev/null", "--confidence-output"));
  CHECK(contents(dir / "in.png") == "input");
  fs::remove_all(dir);
}

TEST_CASE("OutputSet commits all outputs or none; a symlink at a target is replaced, not followed", "[tools]") {
  const fs::path dir = fresh_dir("fpstereo_test_outputs");
  std::ofstream(dir / "victim") << "victim";
  std::ofstream(dir / "a") << "previous a";
  fs::create_symlink(dir / "victim", dir / "b");
  {
    OutputSet outputs;  // destroyed uncommitted: nothing changes, nothing stays
    outputs.add_file(dir / "a", "a");
    outputs.add_file(dir / "b", "b");
    outputs.stage(dir / "a", "new a");
  }
  CHECK(contents(dir / "a") == "previous a");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);
  OutputSet outputs;
  outputs.add_file(dir / "a", "a");
  outputs.add_file(dir / "b", "b");
  outputs.add_directory(dir / "d", "d");
  outputs.stage(dir / "a", "new a");
  outputs.stage(dir / "b", "new b");
  outputs.stage_in_directory(dir / "d", "x.v", "module x; endmodule\n");
  CHECK_FALSE(fs::exists(dir / "d"));
  outputs.commit();
  CHECK(contents(dir / "a") == "new a");
  CHECK(contents(dir / "b") == "new b");
  CHECK_FALSE(fs::is_symlink(dir / "b"));
  CHECK(contents(dir / "victim") == "victim");
  CHECK(contents(dir / "d" / "x.v") == "module x; endmodule\n");
  CHECK(fs::exists(dir / "d" / kDirectoryMarker));
  fs::remove_all(dir);
}

TEST_CASE("OutputSet swaps a directory in whole, and keeps a directory that holds other files", "[tools]") {
  const fs::path dir = fresh_dir("fpstereo_test_swap");
  const auto emit = [&](const std::string& name) {
    OutputSet outputs;
    outputs.add_directory(dir / "out", "-o directory");
    outputs.stage_in_directory(dir / "out", name, name);
    outputs.commit();
  };
  emit("first.v");
  emit("second.v");  // an earlier output (the marker): replaced whole
  CHECK_FALSE(fs::exists(dir / "out" / "first.v"));
  CHECK(contents(dir / "out" / "second.v") == "second.v");
  fs::remove(dir / "out" / kDirectoryMarker);
  std::ofstream(dir / "out" / "notes.txt") << "mine";
  CHECK_THROWS_WITH(emit("third.v"), Catch::Contains("it holds 'notes.txt', which this run does not write"));
  CHECK(contents(dir / "out" / "notes.txt") == "mine");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // no staged directory left
  fs::remove_all(dir);
}

TEST_CASE("parse_decimal takes plain decimals only", "[tools]") {
  CHECK(parse_decimal("4") == 4.0);
  CHECK(parse_decimal("-2.5e3") == -2500.0);
  CHECK(parse_decimal(".5") == 0.5);
  for (const char* bad : {"", "0x10", "1e-310", "1e999", "inf", "nan", " 1", "1 ", "1e", ".", "+", "1,5"})
    CHECK_FALSE(parse_decimal(bad));
}

TEST_CASE("one_line escapes control characters only; quoted also quotes and backslashes", "[tools]") {
  const char raw[] = "a\nb\rc\td\001e\x7f\0f'g\\h\xc3\xa9";  // with a NUL and UTF-8 é
  const std::string hostile(raw, sizeof raw - 1);
  CHECK(one_line(hostile) == "a\\nb\\rc\\td\\x01e\\x7f\\x00f'g\\h\xc3\xa9");
  CHECK(quoted(hostile) == "'a\\nb\\rc\\td\\x01e\\x7f\\x00f\\'g\\\\h\xc3\xa9'");
  CHECK(one_line("plain text, 'quotes' kept") == "plain text, 'quotes' kept");
  std::string non_const = "x\ny";  // must not pick std::quoted by argument-dependent lookup
  CHECK(quoted(non_const) == "'x\\ny'");
}

TEST_CASE("fill_template replaces each placeholder once and refuses one without a value", "[tools]") {
  const std::map<std::string, std::string> values = {{"TOP", "t"}, {"CONFIG", "@TOP@"}, {"CONFIG_HEADER", "c.hpp"}};
  // A value is not searched again; an '@' outside a placeholder stays.
  CHECK(fill_template("@TOP@_tb @CONFIG@ @CONFIG_HEADER@", values) == "t_tb @TOP@ c.hpp");
  CHECK(fill_template("always @(posedge clk) a@b @ @@ @top@", values) == "always @(posedge clk) a@b @ @@ @top@");
  CHECK(fill_template("", values).empty());
  CHECK_THROWS_AS(fill_template("set x @MISSING@\n", values), std::logic_error);
}
