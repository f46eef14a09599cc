// kinestat: how free and how constrained is a mechanism, a compliant mechanism or a structure?
#include "cli/commands.hpp"

int main(int argc, char** argv) { return kinestat::cli::run(argc, argv); }
