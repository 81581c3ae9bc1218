#pragma once

#include <QtCore/QMap>
#include <QtCore/QSet>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace lk::lkctl {

/// The option parser of the live subcommands: `--name VALUE`, `--name=VALUE` and flags,
/// anywhere among the positional arguments. A word that starts with '-' followed by a digit
/// or '.' is a (negative) number, not an option, so `control 1 speed -100` works; `--` ends
/// the options. Unknown options and options given twice are refused.
class ArgParser {
public:
    /// Declare `--name` ("port", without dashes); `takesValue` false makes it a flag.
    void addOption(const QString &name, bool takesValue);
    /// Parse; false with a one-line `error` naming the offending argument.
    bool parse(const QStringList &args, QString *error);

    const QStringList &positionals() const { return m_positionals; }
    bool isSet(const QString &name) const { return m_values.contains(name); }
    QString value(const QString &name) const { return m_values.value(name); }

    /// The integer value of `--name` in [min, max]; nullopt (with `error`) when it is not.
    std::optional<qint64> intValue(const QString &name, qint64 min, qint64 max,
                                   QString *error) const;
    /// The finite number value of `--name` >= min; nullopt (with `error`) when it is not.
    std::optional<double> numberValue(const QString &name, double min, QString *error) const;

    /// "-100", "-.5", "-1e3": a negative number, not an option.
    static bool looksNumeric(const QString &word);

private:
    QMap<QString, bool> m_declared; ///< name -> takes a value
    QMap<QString, QString> m_values;
    QStringList m_positionals;
};

} // namespace lk::lkctl
