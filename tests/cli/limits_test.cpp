// Files over the stated size limits (docs/limits.md) are refused by the
// commands (run in-process) before they are read: a clear message naming the file and the
// limit, exit status 2, no memory spent on them. The inputs are sparse
// files, so they take no room on disk. "Quickly" is checked by ctest's
// TIMEOUT for *Limits* tests (CMakeLists.txt).
#include "bezcam/limits.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

std::string sparse(const testproc::TempDir& dir, const std::string& name, std::size_t bytes) {
  const std::string path = (dir / name).string();
  const int fd = ::open(path.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
  EXPECT_GE(fd, 0);
  EXPECT_EQ(::ftruncate(fd, static_cast<off_t>(bytes)), 0);
  ::close(fd);
  return path;
}

}  // namespace

TEST(Limits, CommandsRefuseOversizedFilesBeforeReadingThem) {
  testproc::TempDir dir;
  const std::string job = sparse(dir, "huge.json", bezcam::kMaxJobBytes + 1);
  const std::string nc = sparse(dir, "huge.nc", bezcam::kMaxProgramBytes + 1);
  struct Case {
    std::vector<std::string> args;
    std::string file, limit;
  };
  const std::vector<Case> cases = {
      {{"convert", job, "-o", (dir / "out.nc").string()}, job, "32 MiB"},
      {{"check", job}, job, "32 MiB"},
      {{"lint", nc, "--machine", "generic"}, nc, "128 MiB"},
      {{"simulate", "--program", nc}, nc, "128 MiB"},
      {{"preview", "--program", nc, "-o", (dir / "out.svg").string()}, nc, "128 MiB"},
  };
  for (const auto& c : cases) {
    const auto r = bezcam::test::run_cli(c.args);
    EXPECT_EQ(r.status, 2) << c.args[0] << ": " << r.err;
    EXPECT_NE(r.err_first_line().find(c.file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("more than bezcam reads (" + c.limit), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out.nc"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.svg"));
}
