#pragma once
// The text of `villa annotate DIR --status`: progress by status, who labelled how much and how long it
// took, and, when layouts were labelled by two people (the overlap sample of --split), how far they agree.
#include <string>

#include "annotator/session.h"

namespace villa::annotator {

std::string StatusReport(const Session& session);

}  // namespace villa::annotator
