// POSIX implementation of whole-file reads and atomic replacement.
#include "support/files.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace uprog {
namespace {

void set_error(std::string* error, const std::string& what) {
  if (error) *error = what + ": " + std::strerror(errno);
}

std::string parent_dir(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

}  // namespace

std::optional<std::string> read_text_file(const std::string& path, std::string* error) {
  // A directory opens as a stream and reads as nothing (or, measured, as a huge file).
  struct stat st {};
  const bool known = ::stat(path.c_str(), &st) == 0;
  if (known && S_ISDIR(st.st_mode)) {
    errno = EISDIR;
    set_error(error, "cannot open " + path);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    set_error(error, "cannot open " + path);
    return std::nullopt;
  }
  // A regular file is read into a string of its size at once: a string stream copies a large
  // file several times. Other files (a pipe) and a file that changes size meanwhile take the
  // stream.
  if (known && S_ISREG(st.st_mode) && st.st_size > 0) {
    std::string text(static_cast<size_t>(st.st_size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (static_cast<size_t>(in.gcount()) == text.size() &&
        in.peek() == std::ifstream::traits_type::eof())
      return text;
    in.clear();
    in.seekg(0);
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<std::vector<uint8_t>> read_binary_file(const std::string& path, std::string* error) {
  auto text = read_text_file(path, error);
  if (!text) return std::nullopt;
  return std::vector<uint8_t>(text->begin(), text->end());
}

namespace {

// Writes all of `bytes` to `fd`; false with `error` set (naming `what`) when it cannot.
bool write_all(int fd, const void* data, size_t size, const std::string& what, std::string* error) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      set_error(error, "cannot write " + what);
      return false;
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    set_error(error, "cannot flush " + what);
    return false;
  }
  return true;
}

void sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// The named temporary of `path` for this process: one per process, so that two writers of the
// same file never share a half-written one.
std::string temporary_of(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}

// Renames the finished temporary over `path`; on failure the temporary is removed.
bool replace_with(const std::string& temp, const std::string& path, std::string* error) {
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    set_error(error, "cannot replace " + path);
    ::unlink(temp.c_str());
    return false;
  }
  sync_directory(parent_dir(path));
  return true;
}

// The new contents go into a file without a name (O_TMPFILE), which the kernel drops when the
// process dies before it is named: a kill while writing leaves nothing behind. Only the last
// step names it (a link, then the rename), so a named temporary exists for two system calls.
// nullopt when the file system has no nameless files (the caller then writes a named one).
std::optional<bool> write_through_nameless_file(const std::string& path, const void* data,
                                                size_t size, std::string* error) {
#ifdef O_TMPFILE
  const int fd = ::open(parent_dir(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
  if (fd < 0) return std::nullopt;
  const std::string temp = temporary_of(path);
  if (!write_all(fd, data, size, temp, error)) {
    ::close(fd);
    return false;
  }
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  ::unlink(temp.c_str());  // a stale one of an earlier process with this pid
  const bool linked =
      ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) == 0;
  if (!linked) set_error(error, "cannot create " + temp);
  ::close(fd);
  if (!linked) return false;
  return replace_with(temp, path, error);
#else
  (void)path, (void)data, (void)size, (void)error;
  return std::nullopt;
#endif
}

}  // namespace

bool write_file_atomically(const std::string& path, const void* data, size_t size,
                           std::string* error) {
  if (auto done = write_through_nameless_file(path, data, size, error)) return *done;
  const std::string temp = temporary_of(path);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    set_error(error, "cannot create " + temp);
    return false;
  }
  const bool written = write_all(fd, data, size, temp, error);
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    if (written) set_error(error, "cannot flush " + temp);
    ::unlink(temp.c_str());
    return false;
  }
  return replace_with(temp, path, error);
}

int remove_stale_temporaries(const std::string& dir) {
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return 0;
  int removed = 0;
  while (const dirent* entry = ::readdir(d)) {
    const std::string name = entry->d_name;
    const auto mark = name.rfind(".tmp.");
    if (mark == std::string::npos || mark == 0) continue;
    const std::string pid_text = name.substr(mark + 5);
    if (pid_text.empty() || pid_text.size() > 9 ||
        pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    // A writer that still lives may be between its link and its rename: leave its file.
    const auto pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid != ::getpid() && (::kill(pid, 0) == 0 || errno != ESRCH)) continue;
    if (::unlink((dir + "/" + name).c_str()) == 0) ++removed;
  }
  ::closedir(d);
  if (removed > 0) sync_directory(dir);
  return removed;
}

}  // namespace uprog
