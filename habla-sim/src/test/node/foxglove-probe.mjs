// An independent Foxglove WebSocket client for HABLA's tests: the official @foxglove/ws-protocol client
// over the `ws` package. It connects, subscribes to the topics named, listens for a while and prints one
// JSON object: the advertised channels, and per topic every message it received (images summarised).
//   node foxglove-probe.mjs ws://127.0.0.1:7098 SECONDS TOPIC...
import wsProtocol from "@foxglove/ws-protocol";
import WebSocket from "ws";

const { FoxgloveClient } = wsProtocol;
const [url, seconds, ...topics] = process.argv.slice(2);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const decoder = new TextDecoder();
const out = { serverInfo: null, channels: [], topics: {}, statuses: [] };
const bySubscription = new Map();
let started = false;

function finish(code) {
  process.stdout.write(JSON.stringify(out) + "\n");
  client.close();
  process.exit(code);
}

client.on("serverInfo", info => { out.serverInfo = info; });
client.on("status", s => out.statuses.push(s));
client.on("error", e => { out.error = String(e); finish(1); });
client.on("advertise", channels => {
  out.channels.push(...channels.map(c => ({ id: c.id, topic: c.topic, encoding: c.encoding,
    schemaName: c.schemaName, schemaEncoding: c.schemaEncoding, schema: JSON.parse(c.schema) })));
  for (const c of channels) {
    if (topics.includes(c.topic)) {
      bySubscription.set(client.subscribe(c.id), c.topic);
      out.topics[c.topic] = [];
    }
  }
  if (!started) {
    started = true;
    setTimeout(() => finish(0), Number(seconds) * 1000);
  }
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const topic = bySubscription.get(subscriptionId);
  const msg = JSON.parse(decoder.decode(data));
  if (typeof msg.data === "string") {
    const bytes = Buffer.from(msg.data, "base64");
    msg.dataBytes = bytes.length;
    msg.dataHead = Array.from(bytes.subarray(0, 4));
    delete msg.data;
  }
  out.topics[topic].push({ receiveNs: timestamp.toString(), msg });
});
setTimeout(() => { out.error = "no advertise within 20 s"; finish(1); }, 20000 + Number(seconds) * 1000);
