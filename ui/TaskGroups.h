// The TaskRunner groups of the session's background stages: a new task cancels the older one of its
// group, and a new mesh or new clusters cancel the groups that depend on them.
#pragma once

#include <QString>

namespace conescope::taskgroups {

inline const QString load = QStringLiteral("load");
inline const QString clusters = QStringLiteral("clusters");
inline const QString orbit = QStringLiteral("orbit");
inline const QString exports = QStringLiteral("export");
inline const QString comparison = QStringLiteral("comparison");
inline const QString lod = QStringLiteral("lod");
inline const QString granularity = QStringLiteral("granularity");

}  // namespace conescope::taskgroups
