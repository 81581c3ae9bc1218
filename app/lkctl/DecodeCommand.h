#pragma once

#include "Subcommand.h"

#include "protocol/Series.h"
#include "protocol/StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QHash>

namespace lk::lkctl {

/// `lkctl decode`: bus bytes (hex arguments, hex text or raw bytes on stdin) to one CLI.md
/// JSON object per frame or fault, in stream order.
class DecodeCommand : public Subcommand {
public:
    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    struct Options {
        protocol::DecodeContext context;
        bool binary = false;
        bool fromStdin = false;
        QStringList hex;
    };
    static std::optional<Options> parseOptions(const QStringList &args, QString *problem);

    int decodeArguments(const Options &options, Console &console);
    int decodeStdinText(Console &console);
    int decodeStdinBinary(Console &console);
    int decodeRecordingFile(const QString &path, Console &console);
    /// A candump log, read as a recording of received CAN frames (recording::CandumpLog).
    int decodeCandump(const QByteArray &text, Console &console);
    void feed(const QByteArray &bytes, Console &console);
    int finish(Console &console);
    int usageError(const QString &problem, Console &console) const;
    void print(const protocol::ParseEvent &event, Console &console);
    protocol::DecodeContext contextFor(int id) const;

    protocol::StreamParser m_parser;
    protocol::DecodeContext m_context;
    /// Generations told by 0x12 replies in the stream: they win over --generation.
    QHash<int, protocol::Generation> m_generationById;
    bool m_sawFault = false;
    QByteArray m_firstInput; ///< standard input read to tell a recording by its magic
};

} // namespace lk::lkctl
