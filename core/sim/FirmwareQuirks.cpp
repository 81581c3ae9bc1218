#include "FirmwareQuirks.h"

namespace lk::sim {

namespace {

struct QuirkName {
    const char *name;
    bool FirmwareQuirks::*flag;
};

const QuirkName kQuirks[] = {
    {"accel-ignored", &FirmwareQuirks::accelIgnored},
    {"clear-angle-ignored", &FirmwareQuirks::clearAngleIgnored},
    {"param-write-refused", &FirmwareQuirks::paramWriteRefused},
};

} // namespace

bool FirmwareQuirks::enable(const QString &name)
{
    for (const QuirkName &q : kQuirks) {
        if (name.compare(QLatin1String(q.name), Qt::CaseInsensitive) == 0) {
            this->*q.flag = true;
            return true;
        }
    }
    return false;
}

QStringList FirmwareQuirks::names() const
{
    QStringList out;
    for (const QuirkName &q : kQuirks) {
        if (this->*q.flag)
            out << QLatin1String(q.name);
    }
    return out;
}

QStringList FirmwareQuirks::allNames()
{
    QStringList out;
    for (const QuirkName &q : kQuirks)
        out << QLatin1String(q.name);
    return out;
}

} // namespace lk::sim
