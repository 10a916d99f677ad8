#include "cli/huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace fabform::cli {

namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb";

std::string kernel_policy() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::stringstream text;
  text << in.rdbuf();
  return huge_page_policy(text.str());
}

// This process's arguments as it was started, from the kernel (NUL-separated).
std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::string::size_type from = 0;
  for (std::string::size_type end; (end = text.find('\0', from)) != std::string::npos; from = end + 1)
    args.push_back(text.substr(from, end - from));
  return args;
}

}  // namespace

std::optional<std::string> tunables_with_huge_pages(const char* now) {
  const std::string current = now ? now : "";
  if (current.find(kTunable) != std::string::npos) return std::nullopt;
  return current.empty() ? std::string(kTunable) + "=1" : current + ":" + kTunable + "=1";
}

std::string huge_page_policy(const std::string& enabled_text) {
  const auto open = enabled_text.find('['), close = enabled_text.find(']', open);
  if (open == std::string::npos || close == std::string::npos) return "";
  return enabled_text.substr(open + 1, close - open - 1);
}

bool malloc_gets_huge_pages() {
  const std::string policy = kernel_policy();
  if (policy == "always") return true;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return policy == "madvise" && tunables && std::string(tunables).find(std::string(kTunable) + "=1") != std::string::npos;
}

void restart_with_huge_pages(double nodes) {
  if (nodes < kHugePagesMinNodes || kernel_policy() != "madvise") return;
  const char* before = std::getenv("GLIBC_TUNABLES");
  const std::optional<std::string> tunables = tunables_with_huge_pages(before);
  if (!tunables) return;
  const std::optional<std::string> kept = before ? std::optional<std::string>(before) : std::nullopt;
  std::vector<std::string> args = own_arguments();
  if (args.empty()) return;
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv.data());
  // The restart failed: go on as started.
  if (kept) setenv("GLIBC_TUNABLES", kept->c_str(), 1);
  else unsetenv("GLIBC_TUNABLES");
}

}  // namespace fabform::cli
