#include "RecordingDecode.h"

#include "Console.h"
#include "Subcommand.h"

#include <protocol/FieldJson.h>
#include <recording/RecordTraffic.h>
#include <recording/RecordedFrameParser.h>
#include <recording/RecordingReader.h>

#include <QtCore/QFile>

namespace lk::lkctl {

using recording::RecordedFrame;
using recording::RecordEvent;

namespace {

QString noteText(const RecordEvent &r)
{
    // The Traffic view's wording, one record at a time.
    const auto notes = recording::trafficEventsOf({r}, {});
    return notes.isEmpty() ? QString() : notes.first().text;
}

} // namespace

bool isRecordingFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && recording::RecordingReader::hasMagic(f.read(8));
}

int decodeRecording(recording::RecordingReader &reader, Console &console)
{
    bool sawFault = false;
    recording::RecordedFrameParser parser(reader.header().context,
                                          recording::linkOf(reader.header()));
    const auto sink = [&](const RecordedFrame &f) {
        QJsonObject o = protocol::FieldJson::eventObject(f.event, f.context);
        sawFault = sawFault || protocol::FieldJson::isError(o);
        o.insert(QStringLiteral("time_s"), double(f.timeNs) * 1e-9);
        o.insert(QStringLiteral("wire"),
                 f.transmitted ? QStringLiteral("tx") : QStringLiteral("rx"));
        console.out(protocol::FieldJson::toJsonLine(o) + '\n');
    };
    RecordEvent e;
    while (reader.next(&e)) {
        parser.feed(e, sink);
        if (e.kind == RecordEvent::Kind::Link || e.kind == RecordEvent::Kind::Dropped) {
            QJsonObject o{{QStringLiteral("note"), noteText(e)},
                          {QStringLiteral("time_s"), double(e.timeNs) * 1e-9}};
            console.out(protocol::FieldJson::toJsonLine(o) + '\n');
        }
    }
    parser.finish(sink);
    console.flush();
    if (reader.error().isError()) {
        console.errLine(QStringLiteral("lkctl decode: %1").arg(reader.error().message));
        return kExitBadData;
    }
    return sawFault ? kExitBadData : kExitOk;
}

} // namespace lk::lkctl
