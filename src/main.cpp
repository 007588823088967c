#include "pbrfit/cli/commands.hpp"

int main(int argc, char** argv) { return pbrfit::cli::main_entry(argc, argv); }
