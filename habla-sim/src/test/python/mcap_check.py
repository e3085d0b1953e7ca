"""An independent MCAP check for HABLA's tests, with the official Python MCAP library (`mcap`): reads the
summary (schemas, channels, statistics) and every message with CRC validation, and prints one JSON object.

    python3 mcap_check.py FILE.mcap
"""
import json
import sys

from mcap.reader import make_reader


def main(path):
    with open(path, "rb") as f:
        reader = make_reader(f, validate_crcs=True)
        summary = reader.get_summary()
        out = {
            "schemas": sorted({s.name for s in summary.schemas.values()}),
            "schemaEncodings": sorted({s.encoding for s in summary.schemas.values()}),
            "channels": {c.topic: {"encoding": c.message_encoding, "schema": summary.schemas[c.schema_id].name}
                         for c in summary.channels.values()},
            "statistics": {"messageCount": summary.statistics.message_count,
                           "chunkCount": summary.statistics.chunk_count},
            "topics": {},
            "metadata": {m.name: sorted(m.metadata.keys()) for m in reader.iter_metadata()},
        }
        for schema, channel, message in reader.iter_messages():
            json.loads(message.data)
            out["topics"][channel.topic] = out["topics"].get(channel.topic, 0) + 1
    print(json.dumps(out))


if __name__ == "__main__":
    main(sys.argv[1])
