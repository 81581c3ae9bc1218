#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QCoreApplication>
#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace lk::ui {

/// How to get permission for serial ports on this Linux distribution: the group that owns
/// them (dialout on Debian, Ubuntu and Fedora, uucp on Arch) and the exact command that adds
/// the user to it, found from os-release's ID and ID_LIKE.
struct SerialGroupAdvice {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::SerialGroupAdvice)
public:
    QString distribution; ///< PRETTY_NAME (or NAME, or ID); empty when unknown
    QString group;        ///< "dialout", "uucp"
    bool known = false;   ///< the distribution was recognised (else dialout is a guess)

    /// `sudo usermod -aG <group> $USER`
    QString command() const;
    /// A sentence for the user: the command, then log out and back in.
    QString explanation() const;

    /// KEY=value lines of os-release, quotes and escapes removed; comments skipped.
    static QMap<QString, QString> parseOsRelease(const QByteArray &text);
    static SerialGroupAdvice fromOsRelease(const QByteArray &text);
    /// From /etc/os-release, else /usr/lib/os-release (the os-release(5) order).
    static SerialGroupAdvice forThisSystem();
    /// From the first of `paths` that is a regular file of at most kMaxOsReleaseBytes.
    static SerialGroupAdvice fromFirstReadable(const QStringList &paths);

    /// os-release is a few hundred bytes: a larger file (or a FIFO, a device) is skipped.
    static constexpr qint64 kMaxOsReleaseBytes = 64 * 1024;
};

} // namespace lk::ui
