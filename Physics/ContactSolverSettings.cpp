// The contact solver ids (ContactSolverSettings.h).
#include "Physics/ContactSolverSettings.h"

#include "Physics/EnumIds.h"

namespace {

constexpr EnumId<ContactSolver> kIds[] = {
    {ContactSolver::Book, "book"}, {ContactSolver::Accumulated, "accumulated"}, {ContactSolver::Soft, "soft"}};

}  // namespace

const char* ToString(ContactSolver solver) { return IdOf(kIds, solver); }

bool ParseContactSolver(const std::string& text, ContactSolver* out) { return ParseId(kIds, text, out); }

std::string ContactSolverIds() { return JoinIds(kIds); }
