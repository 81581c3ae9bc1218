#include "SerialGroupAdvice.h"

#include <system/BoundedFile.h>

#include <QtCore/QStringList>

namespace lk::ui {

namespace {
/// The serial group of a distribution ID (os-release ID or one of ID_LIKE); empty: unknown.
QString groupOf(const QString &id)
{
    static const QMap<QString, QString> groups{
        {QStringLiteral("debian"), QStringLiteral("dialout")},
        {QStringLiteral("ubuntu"), QStringLiteral("dialout")},
        {QStringLiteral("fedora"), QStringLiteral("dialout")},
        {QStringLiteral("rhel"), QStringLiteral("dialout")},
        {QStringLiteral("suse"), QStringLiteral("dialout")},
        {QStringLiteral("opensuse"), QStringLiteral("dialout")},
        {QStringLiteral("arch"), QStringLiteral("uucp")},
        {QStringLiteral("gentoo"), QStringLiteral("uucp")},
    };
    return groups.value(id);
}

QString unquote(QString value)
{
    value = value.trimmed();
    if (value.size() >= 2 &&
        (value.front() == QLatin1Char('"') || value.front() == QLatin1Char('\'')) &&
        value.back() == value.front())
        value = value.mid(1, value.size() - 2);
    // Shell escapes os-release allows inside double quotes: \" \\ \$ \`
    static const QString escaped = QStringLiteral("\"\\$`");
    QString out;
    for (int i = 0; i < value.size(); ++i) {
        if (value.at(i) == QLatin1Char('\\') && i + 1 < value.size() &&
            escaped.contains(value.at(i + 1)))
            ++i;
        out += value.at(i);
    }
    return out;
}
} // namespace

QString SerialGroupAdvice::command() const
{
    return QStringLiteral("sudo usermod -aG %1 $USER").arg(group);
}

QString SerialGroupAdvice::explanation() const
{
    if (known)
        return tr("On %1 serial ports belong to the group %2. Add yourself to it with the "
                  "command below, then log out and back in (or restart) so that the new group "
                  "applies.")
            .arg(distribution, group);
    return tr("Serial ports usually belong to the group %1 (uucp on Arch-like systems; "
              "ls -l on the port shows its group). Add yourself to it with the command below, "
              "then log out and back in (or restart) so that the new group applies.")
        .arg(group);
}

QMap<QString, QString> SerialGroupAdvice::parseOsRelease(const QByteArray &text)
{
    QMap<QString, QString> fields;
    const QStringList lines = QString::fromUtf8(text).split(QLatin1Char('\n'));
    for (const QString &raw : lines) {
        const QString line = raw.trimmed();
        const int eq = line.indexOf(QLatin1Char('='));
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')) || eq <= 0)
            continue;
        fields.insert(line.left(eq).trimmed(), unquote(line.mid(eq + 1)));
    }
    return fields;
}

SerialGroupAdvice SerialGroupAdvice::fromOsRelease(const QByteArray &text)
{
    const QMap<QString, QString> f = parseOsRelease(text);
    SerialGroupAdvice advice;
    advice.distribution = f.value(QStringLiteral("PRETTY_NAME"),
                                  f.value(QStringLiteral("NAME"), f.value(QStringLiteral("ID"))));
    // ID first (the system itself), then ID_LIKE in its order (closest relative first).
    QStringList ids{f.value(QStringLiteral("ID")).toLower()};
    ids << f.value(QStringLiteral("ID_LIKE")).toLower().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    for (const QString &id : ids) {
        advice.group = groupOf(id);
        if (!advice.group.isEmpty()) {
            advice.known = true;
            return advice;
        }
    }
    advice.group = QStringLiteral("dialout");
    return advice;
}

SerialGroupAdvice SerialGroupAdvice::forThisSystem()
{
    return fromFirstReadable(
        {QStringLiteral("/etc/os-release"), QStringLiteral("/usr/lib/os-release")});
}

SerialGroupAdvice SerialGroupAdvice::fromFirstReadable(const QStringList &paths)
{
    for (const QString &path : paths) {
        // Bounded like every file read, so an odd system cannot hang or exhaust lkstudio.
        const system::BoundedRead file = system::BoundedFile::read(path, kMaxOsReleaseBytes);
        if (file.ok())
            return fromOsRelease(file.bytes);
    }
    return fromOsRelease({});
}

} // namespace lk::ui
