#include "src/output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/errors.h"

namespace sandpic {
namespace fs = std::filesystem;

namespace {
std::string folder_of(const std::string& path) {
  fs::path p(path);
  return p.has_parent_path() ? p.parent_path().string() : ".";
}
}  // namespace

std::optional<std::string> read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

void check_writable(const std::string& path) {
  if (path.empty()) throw InputError("an output path is empty");
  std::string dir = folder_of(path);
  if (!fs::is_directory(dir)) throw InputError("cannot write '" + path + "': folder '" + dir + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0) throw InputError("cannot write '" + path + "': folder '" + dir + "' is not writable");
  if (fs::is_directory(path)) throw InputError("cannot write '" + path + "': it is a folder");
}

void check_folder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir) || access(dir.c_str(), W_OK) != 0)
    throw InputError("cannot write into folder '" + dir + "'");
}

void write_atomic(const std::string& path, std::string_view bytes) {
  std::string tmp = path + ".tmp-XXXXXX";
  int fd = mkstemp(tmp.data());
  if (fd < 0) throw InputError("cannot write '" + path + "': " + std::strerror(errno));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) {
      int err = errno;
      close(fd);
      unlink(tmp.c_str());
      throw InputError("cannot write '" + path + "': " + std::strerror(err));
    }
    done += size_t(n);
  }
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  if (close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    unlink(tmp.c_str());
    throw InputError("cannot write '" + path + "': " + std::strerror(err));
  }
}

}  // namespace sandpic
