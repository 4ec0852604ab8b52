#include "handlers/static_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace implicitizer::server {
namespace {

namespace fs = std::filesystem;

// A temporary tree: root/index.html, root/app.js, root/sub/index.html,
// root/escape -> ../secret.txt, root/escape_dir -> .., and secret.txt beside root.
class StaticFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937_64 random(std::random_device{}());
    base_ = fs::temp_directory_path() / ("implicitizer_static_" + std::to_string(random()));
    root_ = base_ / "root";
    fs::create_directories(root_ / "sub");
    write(root_ / "index.html", "<p>home</p>");
    write(root_ / "app.js", "1;");
    write(root_ / "sub" / "index.html", "<p>sub</p>");
    write(base_ / "secret.txt", "secret");
    fs::create_symlink(base_ / "secret.txt", root_ / "escape");
    fs::create_directory_symlink(base_, root_ / "escape_dir");
  }
  void TearDown() override { fs::remove_all(base_); }

  static void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

  fs::path resolved(std::string_view target) const {
    const auto r = resolve_static_path(root_, target);
    return std::holds_alternative<fs::path>(r) ? std::get<fs::path>(r) : fs::path();
  }
  StaticPathError error(std::string_view target) const {
    const auto r = resolve_static_path(root_, target);
    EXPECT_TRUE(std::holds_alternative<StaticPathError>(r)) << target;
    return std::holds_alternative<StaticPathError>(r) ? std::get<StaticPathError>(r) : StaticPathError::not_found;
  }

  fs::path base_;
  fs::path root_;
};

TEST_F(StaticFilesTest, ServesFilesAndIndexes) {
  const fs::path root = fs::canonical(root_);
  EXPECT_EQ(resolved("/"), root / "index.html");
  EXPECT_EQ(resolved("/app.js"), root / "app.js");
  EXPECT_EQ(resolved("/app.js?v=3"), root / "app.js");
  EXPECT_EQ(resolved("/sub/"), root / "sub" / "index.html");
  EXPECT_EQ(resolved("/sub"), root / "sub" / "index.html");
  EXPECT_EQ(resolved("//app.js"), root / "app.js");
  EXPECT_EQ(resolved("/%61pp.js"), root / "app.js");
}

TEST_F(StaticFilesTest, RefusesTraversalHoweverSpelt) {
  for (const char* target :
       {"/../secret.txt", "/sub/../../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E/secret.txt", "/.%2e/secret.txt",
        "/sub/%2e%2e%2f%2e%2e%2fsecret.txt", "/..%2fsecret.txt", "/..%5csecret.txt", "/./index.html", "/app.js%00.html",
        "/%zz", "/%2", "http://host/secret.txt", "*"}) {
    EXPECT_EQ(error(target), StaticPathError::invalid) << target;
  }
}

TEST_F(StaticFilesTest, SymlinksLeadingOutsideAreAbsent) {
  EXPECT_EQ(error("/escape"), StaticPathError::not_found);
  EXPECT_EQ(error("/escape_dir/secret.txt"), StaticPathError::not_found);
  EXPECT_EQ(error("/missing.html"), StaticPathError::not_found);
  EXPECT_EQ(error("/etc/passwd"), StaticPathError::not_found);
}

TEST(ContentType, ByExtension) {
  EXPECT_EQ(content_type_for("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type_for("app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type_for("style.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type_for("x.png"), "image/png");
  EXPECT_EQ(content_type_for("x.unknown"), "application/octet-stream");
}

}  // namespace
}  // namespace implicitizer::server
