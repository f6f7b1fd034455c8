#include "src/cli/commands.h"

int main(int argc, char** argv) { return sandpic::cli_main(argc, argv); }
