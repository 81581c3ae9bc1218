#include "Console.h"

#include <cerrno>
#include <unistd.h>

namespace lk::lkctl {

Console::Console(int inFd, int outFd, int errFd) : m_in(inFd)
{
    m_out.open(outFd, QIODevice::WriteOnly, QFileDevice::DontCloseHandle);
    m_err.open(errFd, QIODevice::WriteOnly | QIODevice::Unbuffered, QFileDevice::DontCloseHandle);
}

Console::~Console()
{
    flush();
}

void Console::out(const QByteArray &bytes)
{
    m_out.write(bytes);
}

void Console::outLine(const QString &line)
{
    m_out.write(line.toUtf8() + '\n');
}

void Console::errLine(const QString &line)
{
    flush(); // keep what was printed before the message ahead of it on a shared terminal
    m_err.write(line.toUtf8() + '\n');
}

void Console::flush()
{
    m_out.flush();
}

QByteArray Console::readSome(qsizetype max)
{
    // QFile's buffered read on a pipe waits until its whole buffer is full; read(2) returns
    // what is there, which is what decoding a live capture needs.
    QByteArray buf(max, Qt::Uninitialized);
    for (;;) {
        const ssize_t n = ::read(m_in, buf.data(), static_cast<size_t>(max));
        if (n >= 0) {
            buf.truncate(n);
            return buf;
        }
        if (errno != EINTR) {
            m_inputFailed = true;
            return {};
        }
    }
}

} // namespace lk::lkctl
