#pragma once

namespace sandpic {

// Exit codes: 0 done, 2 bad input (one line naming the key or file), 3 the
// simulation failed. No output file is written unless the run succeeded.
int cli_main(int argc, char** argv);

}  // namespace sandpic
