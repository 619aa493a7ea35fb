// The contact solver ids (ContactSolverSettings.h).
#include "Physics/ContactSolverSettings.h"

namespace {

struct IdName {
    ContactSolver solver;
    const char* id;
};
constexpr IdName kIds[] = {
    {ContactSolver::Book, "book"}, {ContactSolver::Accumulated, "accumulated"}, {ContactSolver::Soft, "soft"}};

}  // namespace

const char* ToString(ContactSolver solver) {
    for (const IdName& e : kIds)
        if (e.solver == solver) return e.id;
    return "unknown";
}

bool ParseContactSolver(const std::string& text, ContactSolver* out) {
    for (const IdName& e : kIds)
        if (text == e.id) {
            if (out != nullptr) *out = e.solver;
            return true;
        }
    return false;
}

std::string ContactSolverIds() {
    std::string ids;
    for (const IdName& e : kIds) {
        if (!ids.empty()) ids += ", ";
        ids += e.id;
    }
    return ids;
}
