#include "LocalTimeZone.h"

#include <QtCore/QByteArray>
#include <QtCore/QFileInfo>
#include <QtCore/QtGlobal>

namespace lk::system {

void LocalTimeZone::readOnce()
{
    if (qEnvironmentVariableIsSet("TZ"))
        return;
    // Without the file glibc uses UTC either way; TZ would then name a file that is not there.
    if (!QFileInfo::exists(QStringLiteral("/etc/localtime")))
        return;
    qputenv("TZ", QByteArrayLiteral(":/etc/localtime"));
}

} // namespace lk::system
