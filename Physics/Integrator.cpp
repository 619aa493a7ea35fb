// STUB (issue 4 replaces this file).
#include "Integrator.h"

const char* ToString(Integrator) { return "euler"; }
bool ParseIntegrator(const std::string&, Integrator*) { return false; }
std::string IntegratorIds() { return "euler"; }
