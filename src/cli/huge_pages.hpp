#pragma once
// Transparent huge pages for large fabrics. A large run's arrays span gigabytes read in scattered
// order: in 4 kB pages the processor's address cache misses and every page is a fault. With 2 MB
// pages the dome at a million nodes takes an eighth of the faults; whether that saves time depends
// on how much memory the kernel must compact to find them (docs/speed.md, "Huge pages"). Where the kernel gives
// huge pages only to memory that asks for them (transparent_hugepage "madvise", Debian's default),
// glibc's malloc asks when its tunable glibc.malloc.hugetlb=1 is set, which it reads only as the
// process starts; so a run of a large fabric starts itself again, in place (the same process,
// arguments and open files), with the tunable added. A glibc.malloc.hugetlb the user set is kept.
#include <optional>
#include <string>

namespace fabform::cli {

/// The fabrics from which a run asks for huge pages: from here a run takes seconds, beside which
/// the restart (a process start) is small.
constexpr double kHugePagesMinNodes = 40'000;

/// GLIBC_TUNABLES with malloc's huge pages asked for, from its value now (null: unset); nothing
/// where it already names glibc.malloc.hugetlb.
std::optional<std::string> tunables_with_huge_pages(const char* now);

/// The policy bracketed in the text of /sys/kernel/mm/transparent_hugepage/enabled
/// ("always [madvise] never" → "madvise"); empty if none is.
std::string huge_page_policy(const std::string& enabled_text);

/// Whether this process's malloc gets huge pages: the kernel gives them always, or on request
/// and the process started with glibc.malloc.hugetlb=1.
bool malloc_gets_huge_pages();

/// For a fabric of `nodes` nodes from kHugePagesMinNodes, where the kernel gives huge pages on
/// request and malloc does not yet ask: starts this process again with the tunable (no return).
/// Otherwise, or if it cannot, it returns and the run goes on as it is.
void restart_with_huge_pages(double nodes);

}  // namespace fabform::cli
