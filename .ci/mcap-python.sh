#!/usr/bin/env bash
# Recordings and the plant's own MCAP tools: a demo recording (ergocell writes zstd chunks) is read
# by Python's `mcap` reader and rewritten by Python's `mcap` writer, once with its default zstd
# chunks and once with lz4; `ergocell report` of each rewrite gives the same frames and summary CSV
# as of the original.
# Usage: .ci/mcap-python.sh target/release/ergocell   (needs `pip install mcap`, as .ci/run does)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" --log error demo --cycles 1 --no-faults --out "$tmp/orig.mcap" > /dev/null
python3 - "$tmp" <<'PY'
import sys
from mcap.reader import make_reader
from mcap.writer import CompressionType, Writer

tmp = sys.argv[1]
with open(f"{tmp}/orig.mcap", "rb") as f:
    reader = make_reader(f)
    header = reader.get_header()
    summary = reader.get_summary()
    compressions = {c.compression for c in summary.chunk_indexes}
    assert compressions == {"zstd"}, compressions
    messages = list(reader.iter_messages(log_time_order=False))
    metadata = list(reader.iter_metadata())
print(f"   Python's mcap read ergocell's recording: {len(messages)} messages in "
      f"{len(summary.chunk_indexes)} zstd chunks")
for name, compression in [("zstd", CompressionType.ZSTD), ("lz4", CompressionType.LZ4)]:
    with open(f"{tmp}/{name}.mcap", "wb") as out:
        w = Writer(out, compression=compression)
        w.start(profile=header.profile, library="python mcap")
        schemas, channels = {}, {}
        for schema, channel, m in messages:
            if schema.id not in schemas:
                schemas[schema.id] = w.register_schema(schema.name, schema.encoding, schema.data)
            if channel.id not in channels:
                channels[channel.id] = w.register_channel(
                    channel.topic, channel.message_encoding, schemas[schema.id], channel.metadata)
            w.add_message(channels[channel.id], m.log_time, m.data, m.publish_time, m.sequence)
        for md in metadata:
            w.add_metadata(md.name, md.metadata)
        w.finish()
    with open(f"{tmp}/{name}.mcap", "rb") as f:
        written = {c.compression for c in make_reader(f).get_summary().chunk_indexes}
    assert written == {name}, (name, written)
PY
for name in orig zstd lz4; do
  "$bin" --log error report "$tmp/$name.mcap" --out "$tmp/$name.html" \
    --csv "$tmp/$name.csv" --summary-csv "$tmp/$name-summary.csv" > /dev/null
done
for name in zstd lz4; do
  cmp -s "$tmp/orig.csv" "$tmp/$name.csv" && cmp -s "$tmp/orig-summary.csv" "$tmp/$name-summary.csv" \
    || { echo "FAIL: the report of Python's $name rewrite differs from the original's" >&2; exit 1; }
done
echo "   ok: Python's mcap rewrites (zstd, lz4 chunks) report the same $(($(wc -l < "$tmp/orig.csv") - 1)) frames and summary as the original"
