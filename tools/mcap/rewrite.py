"""Rewrites an MCAP recording with other chunk compression, as a plant's own tools would write it.

    python3 tools/mcap/rewrite.py IN.mcap OUT.mcap none|lz4|zstd

Python's `mcap` package (pip install mcap zstandard lz4) reads every message and metadata record of
IN and writes them to OUT in the same order, in chunks of 768 KiB compressed as asked. docs/
measurements.md compares `ergocell report` on an 8-hour shift so rewritten. OUT must not exist.
"""

import os
import sys

from mcap.reader import make_reader
from mcap.writer import CompressionType, Writer

KINDS = {"none": CompressionType.NONE, "lz4": CompressionType.LZ4, "zstd": CompressionType.ZSTD}


def main() -> int:
    if len(sys.argv) != 4 or sys.argv[3] not in KINDS:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    src, dst, kind = sys.argv[1:]
    if os.path.exists(dst):
        print(f"{dst} exists: not overwritten", file=sys.stderr)
        return 2
    if os.path.realpath(src) == os.path.realpath(dst):
        print("the output would overwrite the input", file=sys.stderr)
        return 2
    with open(src, "rb") as f, open(dst, "xb") as out:
        reader = make_reader(f)
        header = reader.get_header()
        writer = Writer(out, compression=KINDS[kind], chunk_size=768 * 1024)
        writer.start(profile=header.profile, library=header.library)
        schemas, channels = {}, {}
        for schema, channel, m in reader.iter_messages(log_time_order=False):
            if schema is not None and schema.id not in schemas:
                schemas[schema.id] = writer.register_schema(schema.name, schema.encoding, schema.data)
            if channel.id not in channels:
                channels[channel.id] = writer.register_channel(
                    channel.topic,
                    channel.message_encoding,
                    schemas.get(channel.schema_id, 0),
                    channel.metadata,
                )
            writer.add_message(channels[channel.id], m.log_time, m.data, m.publish_time, m.sequence)
        for md in reader.iter_metadata():
            writer.add_metadata(md.name, md.metadata)
        writer.finish()
    return 0


if __name__ == "__main__":
    sys.exit(main())
