#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QFile>
#include <QtCore/QString>

namespace lk::lkctl {

/// Standard input, output and error of lkctl as byte streams. Output is buffered until
/// flush() (and on destruction) so that many JSON lines cost few writes; error lines are
/// written at once. Input is read as it arrives, so that a live pipe is decoded live.
class Console {
public:
    Console(int inFd = 0, int outFd = 1, int errFd = 2);
    ~Console();
    Console(const Console &) = delete;
    Console &operator=(const Console &) = delete;

    void out(const QByteArray &bytes);
    void outLine(const QString &line); ///< UTF-8, newline appended
    void errLine(const QString &line); ///< UTF-8, newline appended, flushed with stdout first
    void flush();
    /// Standard output could not be written (the reader went away, the disk is full).
    bool outputFailed() const { return m_out.error() != QFileDevice::NoError; }

    /// Blocks until bytes arrive on standard input, returns up to max of them; empty at the
    /// end of input or on a read error (then inputFailed() is true).
    QByteArray readSome(qsizetype max = 65536);
    bool inputFailed() const { return m_inputFailed; }

private:
    int m_in;
    QFile m_out;
    QFile m_err;
    bool m_inputFailed = false;
};

} // namespace lk::lkctl
