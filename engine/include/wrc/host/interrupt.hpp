// A run of the wrc executable stopped by a signal: SIGINT (Ctrl-C), SIGTERM (a SLURM job at its time limit, GNU
// parallel's --timeout, kill) or SIGHUP (its terminal closed). It removes the temporary files it was writing (the
// outputs already renamed into place are complete; the one being written keeps its previous content, or does not
// exist) and ends by the signal's default action: the shell's exit status 128 + the signal's number (130, 143, 129),
// and a calling shell or GNU parallel sees that the run was interrupted, not that it failed.
#pragma once

namespace wrc::host {

// Installs the handler for SIGINT, SIGTERM and SIGHUP, on the thread that runs the script, before any other thread
// starts. A signal the process inherited as ignored (nohup, a background job of a script) stays ignored.
void remove_temporaries_when_interrupted();

}  // namespace wrc::host
