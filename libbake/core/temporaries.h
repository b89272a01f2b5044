// Temporary files of atomic writes (core/atomic_file.h, the image writer) are registered while they
// exist, so that a bake stopped by a catchable signal removes them before it dies: Ctrl-C (SIGINT), a
// build system cancelling a job (SIGTERM, SIGHUP), a pipe closed under it (SIGPIPE), or a file-size
// limit hit in the middle of a write (SIGXFSZ). The handler unlinks the registered files and then
// lets the signal take its default course, so the exit status still says which signal it was. It
// stays installed until the files are gone (a second signal on another thread runs it too rather than
// ending the process first) and waits for a temporary being created on another thread; writers use
// the open descriptor, not the name, so nothing re-creates a removed temporary.
// Targets are only ever replaced by rename, so an interrupted bake leaves every earlier output
// byte-identical; SIGKILL cannot be caught and may leave a hidden `.NAME.tmp.XXXXXX` beside the
// target, never a partial target.
#pragma once

#include <filesystem>
#include <string>

namespace bake {

// Creates a temporary file like mkstemps ("....XXXXXX" followed by `suffixLength` characters; the
// pattern is rewritten with the name) and registers it in a way no signal can slip through: the name
// is registered before the file is created. Installs the handlers on first use. Returns the open
// descriptor, or -1 with errno set. At most kMaxRegisteredTemporaries are tracked at once; more are
// still created, only not removed on a signal.
int createRegisteredTemporary(std::string& pattern, int suffixLength = 0);
// Forgets a temporary that was renamed into place or removed.
void unregisterTemporary(const std::filesystem::path& path);

inline constexpr int kMaxRegisteredTemporaries = 64;

}  // namespace bake
