// The handler of an interrupted run (interrupt.hpp).
//
// Why it is safe where it runs (a signal handler may interrupt any code: malloc, stdio, Lua, a rename): it calls only
// functions POSIX lists as async-signal-safe (POSIX.1-2017, 2.4.3: unlink, write, strlen, sigaction, raise,
// pthread_self, pthread_kill), reads the table of temporaries through lock-free atomics (core/files.hpp), and touches
// neither the heap, nor stdio, nor the Lua state. It never returns into the interrupted code either: it re-raises the
// signal with its default action, which ends the process as soon as the handler returns (the signal is blocked while
// it runs). So nothing has to poll a flag: a Lua loop that writes nothing, or a solve in C++ of minutes, stops at once;
// and a script's pcall cannot catch the interruption and go on, as it could catch the error that lua.c's hook raises.
//
// Why no temporary file survives: the files are created by the thread that runs Lua, the process's main thread, and
// each temporary is tracked before it is created and untracked after its rename (AtomicFile). The handler runs on the
// main thread (a signal that lands on a worker thread is passed on to it), so while it unlinks, no file is created or
// renamed, and after it nothing runs. A name tracked and not yet created, or already renamed, is unlinked in vain.
#include "wrc/host/interrupt.hpp"

#include "wrc/core/files.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstring>

namespace wrc::host {
namespace {

pthread_t g_main_thread;

const char* message(int sig) {
  switch (sig) {
    case SIGINT: return "wrc: interrupted by SIGINT: the files being written were removed (exit status 130)\n";
    case SIGTERM: return "wrc: interrupted by SIGTERM: the files being written were removed (exit status 143)\n";
    default: return "wrc: interrupted by SIGHUP: the files being written were removed (exit status 129)\n";
  }
}

void on_signal(int sig) {
  if (!pthread_equal(pthread_self(), g_main_thread)) {  // pthread_equal: a comparison of two ids, nothing more
    pthread_kill(g_main_thread, sig);
    return;
  }
  remove_tracked_temporaries();
  const char* text = message(sig);
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, text, std::strlen(text));
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, nullptr);
  raise(sig);  // pending until this handler returns, then the default action ends the process
}

}  // namespace

void remove_temporaries_when_interrupted() {
  g_main_thread = pthread_self();
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);  // one handler at a time
  sa.sa_flags = SA_RESTART;  // a worker thread that passed a signal on goes on with its system call
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace wrc::host
