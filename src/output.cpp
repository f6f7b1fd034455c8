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

// What a new file or folder gets: mkstemp and mkdtemp make them private.
mode_t public_mode(bool folder) {
  mode_t mask = umask(0);
  umask(mask);
  return (folder ? 0777 : 0666) & ~mask;
}

[[noreturn]] void cannot_write(const std::string& path, int err) {
  throw InputError("cannot write '" + path + "': " + std::strerror(err));
}
}  // namespace

std::optional<std::string> read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

void check_parent_writable(const std::string& path) {
  if (path.empty()) throw InputError("an output path is empty");
  std::string dir = folder_of(path);
  if (!fs::is_directory(dir)) throw InputError("cannot write '" + path + "': folder '" + dir + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0) throw InputError("cannot write '" + path + "': folder '" + dir + "' is not writable");
}

void check_writable(const std::string& path) {
  check_parent_writable(path);
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
  fchmod(fd, public_mode(false));
  if (close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    unlink(tmp.c_str());
    throw InputError("cannot write '" + path + "': " + std::strerror(err));
  }
}

std::string temp_folder_beside(const std::string& path) {
  std::string tmp = path + ".tmp-XXXXXX";
  if (!mkdtemp(tmp.data())) cannot_write(path, errno);
  return tmp;
}

std::string temp_file_beside(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  std::string tmp = path + ".tmp-XXXXXX" + ext;
  int fd = mkstemps(tmp.data(), int(ext.size()));
  if (fd < 0) cannot_write(path, errno);
  close(fd);
  return tmp;
}

void move_into_place(const std::string& tmp, const std::string& path) {
  if (chmod(tmp.c_str(), public_mode(fs::is_directory(tmp))) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0)
    cannot_write(path, errno);
}

}  // namespace sandpic
