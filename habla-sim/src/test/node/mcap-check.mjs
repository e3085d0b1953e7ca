// An independent MCAP check for HABLA's tests, with the official TypeScript MCAP library (@mcap/core):
// the stream reader walks every record of the file with CRC validation (chunks, data section, summary),
// and the indexed reader reads the summary and every message through the chunk indexes. Prints one JSON
// object; exits 1 with {"error"} on the first problem.
//   node mcap-check.mjs FILE.mcap
import { McapStreamReader, McapIndexedReader } from "@mcap/core";
import { loadDecompressHandlers } from "@mcap/support";
import { FileHandleReadable } from "@mcap/nodejs";
import { open, readFile } from "node:fs/promises";

const file = process.argv[2];
const out = { records: {}, indexedMessages: 0, topics: {} };
try {
  const decompressHandlers = await loadDecompressHandlers();
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(await readFile(file));
  for (let r; (r = stream.nextRecord()); ) out.records[r.type] = (out.records[r.type] ?? 0) + 1;
  if (!stream.done()) throw new Error("the stream reader did not reach the end magic");

  const handle = await open(file, "r");
  const reader = await McapIndexedReader.Initialize({ readable: new FileHandleReadable(handle), decompressHandlers });
  out.chunkIndexes = reader.chunkIndexes.length;
  out.statistics = reader.statistics ? {
    messageCount: Number(reader.statistics.messageCount), channelCount: reader.statistics.channelCount,
    chunkCount: reader.statistics.chunkCount, metadataCount: reader.statistics.metadataCount } : null;
  out.schemas = [...reader.schemasById.values()].map(s => ({ id: s.id, name: s.name, encoding: s.encoding }));
  const decoder = new TextDecoder();
  for await (const m of reader.readMessages()) {
    const topic = reader.channelsById.get(m.channelId).topic;
    JSON.parse(decoder.decode(m.data));
    out.topics[topic] = (out.topics[topic] ?? 0) + 1;
    out.indexedMessages++;
  }
  out.metadata = [];
  for await (const m of reader.readMetadata()) out.metadata.push({ name: m.name, keys: [...m.metadata.keys()] });
  await handle.close();
  process.stdout.write(JSON.stringify(out) + "\n");
} catch (e) {
  process.stdout.write(JSON.stringify({ error: String(e && e.stack || e) }) + "\n");
  process.exit(1);
}
