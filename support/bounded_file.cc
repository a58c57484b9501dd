#include "bounded_file.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

namespace gfec::bounded_file {

namespace {

/// The pseudo file systems whose files are the kernel's, not data (linux/magic.h): their sizes
/// say 0 or lie, a read may block (/proc/kmsg), consume (the kernel log) or act (sysfs).
bool kernel_file_system(unsigned long type) {
  switch (type) {
  case 0x9fa0UL:      // procfs
  case 0x62656572UL:  // sysfs
  case 0x64626720UL:  // debugfs
  case 0x74726163UL:  // tracefs
  case 0x73636673UL:  // securityfs
  case 0x27e0ebUL:    // cgroup
  case 0x63677270UL:  // cgroup2
  case 0x62656570UL:  // configfs
  case 0xcafe4a11UL:  // bpf
  case 0xde5e81e4UL:  // efivarfs
  case 0x6165676cUL:  // pstore
  case 0x42494e4dUL:  // binfmt_misc
  case 0x65735543UL:  // fusectl
  case 0xf97cff8cUL:  // selinuxfs
  case 0x43415d53UL:  // smackfs
    return true;
  default: return false;
  }
}

constexpr const char *kKernelFile =
    "a file of /proc, /sys or another of the kernel's pseudo file systems; gfec reads none";

const char *kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

/// Why a file with this status is not read ("" if it may be); `too_large` for the size.
std::string refusal(const struct stat &st, std::size_t max_bytes, bool &too_large) {
  if (S_ISDIR(st.st_mode)) return "it is a folder";
  if (!S_ISREG(st.st_mode))
    return std::string("not a regular file (") + kind_of(st.st_mode) + "); gfec reads no devices, pipes or sockets";
  too_large = st.st_size > 0 && static_cast<std::uintmax_t>(st.st_size) > max_bytes;
  return {};
}

std::string error_reason(int error) {
  return error == ENOENT || error == ENOTDIR ? "no such file"
         : error == EACCES                   ? "permission denied"
                                             : std::strerror(error);
}

}  // namespace

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

Text read(const std::string &path, std::size_t max_bytes) {
  auto refused = [](std::string why) { return Text{std::nullopt, std::move(why), false}; };
  const Text too_large{std::nullopt, {}, true};
  bool large = false;
  // Looked at before it is opened, since opening may act already (a FIFO's open waits for a
  // writer, a device's driver runs), and again on what was opened: the path may have changed
  // in between.
  struct stat st {};
  struct statfs sfs {};
  if (::stat(path.c_str(), &st) != 0) return refused(error_reason(errno));
  if (std::string why = refusal(st, max_bytes, large); !why.empty()) return refused(why);
  if (large) return too_large;
  if (::statfs(path.c_str(), &sfs) == 0 && kernel_file_system(static_cast<unsigned long>(sfs.f_type)))
    return refused(kKernelFile);
  // O_NONBLOCK: should a FIFO or device replace the file after the checks, open() returns at
  // once and fstat refuses it; O_NOCTTY: a terminal never becomes the reader's controlling one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) return refused(error_reason(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &st) != 0) return refused(error_reason(errno));
  if (std::string why = refusal(st, max_bytes, large); !why.empty()) return refused(why);
  if (large) return too_large;
  if (::fstatfs(fd, &sfs) != 0 || kernel_file_system(static_cast<unsigned long>(sfs.f_type)))
    return refused(kKernelFile);
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) return refused(error_reason(errno));

  // read(2) rather than a stream: a filebuf reports a failed read (EIO, or a file like
  // /proc/self/mem that refuses to be read) as the end of the file, and a truncated input would
  // then be taken as whole.
  auto read_some = [fd](char *into, std::size_t count) {
    ssize_t n;
    do n = ::read(fd, into, count);
    while (n < 0 && errno == EINTR);
    return n;
  };
  // Read into a string sized from fstat: appending in chunks would grow it by doubling, and a
  // 90 MB chart would touch three times its size in fresh pages. Reading still goes on to the
  // end of the file, so one that grew meanwhile is read whole and one that shrank is not padded;
  // but never past the bound, whatever the size said.
  std::string text(st.st_size > 0 ? static_cast<std::size_t>(st.st_size) : 0, '\0');
  std::size_t used = 0;
  ssize_t n = 1;
  while (used < text.size() && (n = read_some(text.data() + used, text.size() - used)) > 0)
    used += static_cast<std::size_t>(n);
  text.resize(used);
  char buffer[65536];
  while (n > 0 && text.size() <= max_bytes && (n = read_some(buffer, sizeof buffer)) > 0)
    text.append(buffer, static_cast<std::size_t>(n));
  if (n < 0) return refused(error_reason(errno));
  if (text.size() > max_bytes) return too_large;
  return Text{std::move(text), {}, false};
}

}  // namespace gfec::bounded_file
