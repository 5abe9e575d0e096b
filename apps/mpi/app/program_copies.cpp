#include "apps/mpi/app/program_copies.hpp"

#include <dlfcn.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "apps/mpi/app/program_symbols.hpp"
#include "apps/pipeline/failure.hpp"

namespace gcsim::mpi_layer::app {
namespace fs = std::filesystem;

namespace {

std::string contents_of(const std::string& program) {
  std::error_code ec;
  if (fs::is_directory(program, ec)) throw pipeline::FileError(program + ": is a folder, not a program");
  if (!fs::is_regular_file(program, ec)) throw pipeline::FileError(program + ": no such program file");
  std::ifstream in(program, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw pipeline::FileError(program + ": cannot read it");
  return bytes;
}

// One copy of the program in memory (no file system, nothing to remove): a memfd holding its bytes.
int memory_copy(const std::string& program, const std::string& bytes, int rank) {
  const std::string name = "gcsim-rank-" + std::to_string(rank);
  const int fd = ::memfd_create(name.c_str(), MFD_CLOEXEC);
  if (fd < 0) throw pipeline::FileError(program + ": cannot make an in-memory copy of it: " + std::strerror(errno));
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      throw pipeline::FileError(program + ": cannot write its in-memory copy: " + why);
    }
    done += static_cast<std::size_t>(n);
  }
  return fd;
}

// Every copy's descriptor stays open until all are loaded (below), so the soft limit of open files
// must allow them; raised up to the hard limit when it does not, and set back afterwards.
class OpenFileAllowance {
 public:
  OpenFileAllowance(const std::string& program, int copies) {
    if (::getrlimit(RLIMIT_NOFILE, &saved_) != 0) return;
    const rlim_t needed = static_cast<rlim_t>(copies) + 64;
    if (saved_.rlim_cur != RLIM_INFINITY && saved_.rlim_cur < needed) {
      rlimit raised = saved_;
      raised.rlim_cur = saved_.rlim_max == RLIM_INFINITY ? needed : std::min(needed, saved_.rlim_max);
      if (raised.rlim_cur < needed) {
        throw pipeline::FileError(program + ": " + std::to_string(copies) + " copies need " + std::to_string(needed) +
                                  " open files at once; the hard limit is " + std::to_string(saved_.rlim_max) + " (ulimit -Hn)");
      }
      changed_ = ::setrlimit(RLIMIT_NOFILE, &raised) == 0;
    }
  }
  ~OpenFileAllowance() {
    if (changed_) ::setrlimit(RLIMIT_NOFILE, &saved_);
  }
  OpenFileAllowance(const OpenFileAllowance&) = delete;
  OpenFileAllowance& operator=(const OpenFileAllowance&) = delete;

 private:
  rlimit saved_{};
  bool changed_ = false;
};

// A call gcsim's MPI does not provide would bind to whatever MPI_* the process holds: refused here.
void refuse_missing_functions(const std::string& program, const std::string& bytes) {
  const std::vector<std::string> missing = missing_mpi_functions(bytes);
  if (missing.empty()) return;
  std::string names;
  for (std::size_t i = 0; i < missing.size() && i < 4; ++i) names += (i ? ", " : "") + missing[i];
  if (missing.size() > 4) names += " and " + std::to_string(missing.size() - 4) + " more";
  throw pipeline::FileError(program + ": calls " + names + ", which gcsim's MPI does not provide (its mpi.h does not " +
                            "declare " + (missing.size() == 1 ? "it" : "them") +
                            "; a C compiler took an implicit declaration). The function table of gcsim's MPI README " +
                            "lists what is supported");
}

}  // namespace

ProgramCopies::ProgramCopies(const std::string& program, int copies, CopiesAtEnd at_end) : at_end_(at_end) {
  const std::string bytes = contents_of(program);
  refuse_missing_functions(program, bytes);
  const OpenFileAllowance allowance(program, copies);
  std::vector<int> fds;
  struct Close {
    std::vector<int>& fds;
    ~Close() {
      for (int fd : fds) ::close(fd);
    }
  } close{fds};
  try {
    load(program, bytes, copies, fds);
  } catch (...) {
    unload();  // the copies loaded so far
    throw;
  }
}

void ProgramCopies::load(const std::string& program, const std::string& bytes, int copies, std::vector<int>& fds) {
  for (int rank = 0; rank < copies; ++rank) {
    fds.push_back(memory_copy(program, bytes, rank));
    // The loader takes an object whose name it has loaded already for that object: each copy's
    // name (its descriptor's) is unique while every descriptor is open.
    const std::string path = "/proc/self/fd/" + std::to_string(fds.back());
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      throw pipeline::FileError(program + ": cannot load it as an MPI program (" + (why ? why : "?") +
                                "); build it with gcsim-mpicc or gcsim-mpicxx");
    }
    handles_.push_back(handle);
    auto main = reinterpret_cast<ProgramMain>(::dlsym(handle, "main"));
    if (!main) throw pipeline::FileError(program + ": has no main function");
    mains_.push_back(main);
  }
}

ProgramCopies::~ProgramCopies() {
  if (at_end_ == CopiesAtEnd::leave_to_exit) return;  // the handles stay valid until the process ends
  unload();
}

void ProgramCopies::unload() noexcept {
  for (auto it = handles_.rbegin(); it != handles_.rend(); ++it) ::dlclose(*it);
  handles_.clear();
  mains_.clear();
}

}  // namespace gcsim::mpi_layer::app
