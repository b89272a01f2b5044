// Transparent huge pages for the allocator of a tool that touches a lot of fresh memory. A large bake
// faults in hundreds of megabytes (the 100,000-groove scene of bench/groove-bake: about 115,000 4 KiB
// page faults), and on a virtual machine each fault costs microseconds: more than the parse of the
// scene itself. glibc's malloc (2.35 and later) asks the kernel for 2 MiB pages when the tunable
// glibc.malloc.hugetlb=1 is set, but reads tunables only from the environment when a process starts;
// so such a tool re-executes itself once, after reading its command line, with the tunable set
// (--help and --version never pay for a second start).
#pragma once

#include <cstdint>
#include <string_view>

namespace bake {

// Whether to re-execute: not when GLIBC_TUNABLES is already set (an empty value opts out; the user's
// tunables stand), when the running executable is not the tool (run under valgrind, which executes
// its own binary), when the kernel gives no transparent huge pages ("[never]", or no such file), or
// in a sanitizer build (its allocator is not glibc's).
bool shouldReexecForHugePages(const char* glibcTunables, std::string_view executableName, std::string_view toolName,
                              std::string_view transparentHugePageMode);

// Whether this build's allocator is a sanitizer's (ASan), which ignores glibc's tunables.
bool allocatorIsSanitized();

// Re-executes /proc/self/exe with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 when shouldReexecForHugePages
// says so; returns (and the tool runs as it is) otherwise, or when the exec fails.
void reexecWithHugePages(char** argv, std::string_view toolName);

// The input size from which a bake whose memory follows its input (geobake's mesh) is worth a second
// start: that costs about what the first did (10-25 ms on a virtual machine), while a 1 MiB mesh's
// bake runs for hundreds of milliseconds, 10-25 % of them in page faults (nefertiti.obj, 3.7 MB,
// heat: 0.88 s to 0.73 s for the whole process, medians of three).
inline constexpr std::uintmax_t kHugePagesWorthInputBytes = std::uintmax_t{1} << 20;

// Whether `input` is a file of at least kHugePagesWorthInputBytes (false when it cannot be read).
bool inputWorthHugePages(std::string_view input);

// reexecWithHugePages when inputWorthHugePages(input).
void reexecWithHugePagesForInput(char** argv, std::string_view toolName, std::string_view input);

}  // namespace bake
