// Over 300 lines, on purpose: the devices, their messages and the teacher share one world under one lock.
package org.habla.sim.room;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.hivemq.client.mqtt.MqttClient;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.habla.sim.world.SimClock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated room on an MQTT broker, as Zigbee2MQTT 2.x would show its devices (2.x gives {@code illuminance} in
 * lux and availability as JSON; 1.x gave many sensors' raw {@code illuminance} and the lux in
 * {@code illuminance_lux}, and plain {@code online}/{@code offline}):
 *
 * <pre>
 *   zigbee2mqtt/bridge/state                 {"state":"online"}  retained; the will says offline
 *   zigbee2mqtt/ZONE_motion                  {"occupancy":true,"illuminance":312,"battery":100,...}
 *   zigbee2mqtt/ZONE_lamp                    {"state":"ON","brightness":254}     after every /set, and at start
 *   zigbee2mqtt/ZONE_lamp/set          ◀──   {"state":"ON"|"OFF"|"TOGGLE","brightness":0..254}
 *   zigbee2mqtt/front_door                   {"contact":true,"battery":100}      true: closed
 *   zigbee2mqtt/room_climate                 {"temperature":21.4,"humidity":45.2,"battery":100}
 *   zigbee2mqtt/teacher_button               {"action":"single"} pleasure, {"action":"double"} pain
 *   zigbee2mqtt/DEVICE/availability          {"state":"online"}  retained
 * </pre>
 *
 * Besides the devices it publishes its ground truth on {@link RoomSimOptions#TRUTH_TOPIC} and the teacher's
 * judgements on {@link RoomSimOptions#TEACHER_TOPIC}, for the scenario's report, and takes
 * {@code {"teacher": true|false}} on {@link RoomSimOptions#CONTROL_TOPIC} to send the teacher in or away. While the teacher is there, every
 * lamp command is judged: right when it lights a zone the person is in and daylight leaves dark, or darkens any
 * other zone; the teacher presses the button once for right, twice for wrong.
 */
public final class RoomSim implements SimClock.Stepper, AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(RoomSim.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final double STEP_S = 0.05;
    private static final double TRUTH_PERIOD_S = 0.5;
    private static final double CLIMATE_PERIOD_S = 10;
    private static final double TEACHER_DELAY_S = 0.3;
    private static final int MAX_BRIGHTNESS = 254;

    private final RoomSimOptions options;
    private final RoomModel room;
    private final SimClock clock;
    private final Mqtt5AsyncClient client;
    private final String base;
    private final boolean[] motionSent;
    private final double[] motionReportedS;
    private final ArrayDeque<Reward> rewards = new ArrayDeque<>();
    private Boolean doorSent;
    private volatile Boolean teacherOverride;
    private double truthS = -1;
    private double climateS = -1e9;
    private long judged;
    private long right;

    private record Reward(double atS, boolean good, ObjectNode judgement) {
    }

    private RoomSim(RoomSimOptions options, RoomModel room, SimClock clock, Mqtt5AsyncClient client) {
        this.options = options;
        this.room = room;
        this.clock = clock;
        this.client = client;
        this.base = options.baseTopic();
        this.motionSent = new boolean[room.zones().size()];
        this.motionReportedS = new double[room.zones().size()];
        java.util.Arrays.fill(motionReportedS, -1e9);
    }

    /** Connects to the broker, announces the devices, and starts the room's clock. */
    public static RoomSim start(RoomSimOptions options) throws IOException {
        RoomModel room = RoomModel.standard(options.daySeconds(), options.dayPhase(), options.seed());
        String base = options.baseTopic();
        Mqtt5AsyncClient client = MqttClient.builder().useMqttVersion5()
                .identifier("habla-sim-room-" + Long.toHexString(System.nanoTime() & 0xffffff))
                .serverHost(options.brokerHost()).serverPort(options.brokerPort())
                .automaticReconnectWithDefaultConfig()
                .buildAsync();
        try {
            client.connectWith().cleanStart(true).keepAlive(5)
                    .willPublish().topic(base + "/bridge/state").payload(utf8("{\"state\":\"offline\"}")).retain(true)
                    .qos(MqttQos.AT_LEAST_ONCE).applyWillPublish()
                    .send().get(10, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            throw new IOException("cannot connect to the broker at " + options.brokerHost() + ":" + options.brokerPort()
                    + ": " + (e.getCause() == null ? e : e.getCause().getMessage()), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while connecting to the broker", e);
        }
        SimClock clock = new SimClock(options.speed(), STEP_S);
        RoomSim sim = new RoomSim(options, room, clock, client);
        client.publishes(MqttGlobalPublishFilter.SUBSCRIBED, sim::onSet);
        try {
            client.subscribeWith().topicFilter(base + "/+/set").qos(MqttQos.AT_LEAST_ONCE).send().get(10, TimeUnit.SECONDS);
            client.subscribeWith().topicFilter(RoomSimOptions.CONTROL_TOPIC).qos(MqttQos.AT_LEAST_ONCE).send()
                    .get(10, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            client.disconnect();
            throw new IOException("cannot subscribe to the lamps' /set topics: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while subscribing", e);
        }
        sim.announce();
        clock.add(sim);
        clock.start();
        LOG.info("simulated room on {}:{} under '{}': zones {}", options.brokerHost(), options.brokerPort(), base,
                room.zones());
        return sim;
    }

    public SimClock clock() {
        return clock;
    }

    /** The device names, as Zigbee2MQTT's friendly names. */
    public List<String> devices() {
        List<String> d = new ArrayList<>();
        for (String z : room.zones()) {
            d.add(z + "_motion");
            d.add(z + "_lamp");
        }
        d.add("front_door");
        d.add("room_climate");
        d.add("teacher_button");
        return d;
    }

    private synchronized void announce() {
        publish(base + "/bridge/state", "{\"state\":\"online\"}", true);
        for (String device : devices()) {
            publish(base + "/" + device + "/availability", "{\"state\":\"online\"}", true);
        }
        for (int z = 0; z < room.zones().size(); z++) {
            publishLamp(z);
        }
    }

    @Override
    public synchronized void step(double nowS, double dtS) {
        room.step(dtS);
        for (int z = 0; z < room.zones().size(); z++) {
            boolean motion = room.motion(z);
            if (motion != motionSent[z] || nowS - motionReportedS[z] >= options.reportS()) {
                motionSent[z] = motion;
                motionReportedS[z] = nowS;
                long lux = Math.round(room.lux(z));
                publish(base + "/" + room.zones().get(z) + "_motion", "{\"occupancy\":" + motion + ",\"illuminance\":"
                        + lux + ",\"battery\":100,\"voltage\":3005,\"linkquality\":120}", false);
            }
        }
        boolean closed = room.doorClosed();
        if (doorSent == null || doorSent != closed) {
            doorSent = closed;
            publish(base + "/front_door", "{\"contact\":" + closed + ",\"battery\":100,\"linkquality\":98}", false);
        }
        if (nowS - climateS >= CLIMATE_PERIOD_S) {
            climateS = nowS;
            publish(base + "/room_climate", String.format(java.util.Locale.ROOT,
                    "{\"temperature\":%.2f,\"humidity\":%.1f,\"battery\":100}", room.temperatureC(), room.humidityPct()),
                    false);
        }
        while (!rewards.isEmpty() && rewards.peek().atS() <= nowS) {
            Reward r = rewards.poll();
            publish(base + "/teacher_button", "{\"action\":\"" + (r.good() ? "single" : "double") + "\"}", false);
            publish(RoomSimOptions.TEACHER_TOPIC, r.judgement().toString(), false);
        }
        if (nowS - truthS >= TRUTH_PERIOD_S) {
            truthS = nowS;
            publish(RoomSimOptions.TRUTH_TOPIC, truth(nowS).toString(), false);
        }
    }

    private ObjectNode truth(double nowS) {
        ObjectNode t = JSON.createObjectNode().put("t", nowS);
        int p = room.personZone();
        if (p >= 0) {
            t.put("person", room.zones().get(p));
        } else {
            t.putNull("person");
        }
        ObjectNode lux = t.putObject("lux");
        ObjectNode daylight = t.putObject("daylight");
        ObjectNode lamps = t.putObject("lamps");
        ObjectNode wants = t.putObject("wantsLight");
        for (int z = 0; z < room.zones().size(); z++) {
            String name = room.zones().get(z);
            lux.put(name, Math.round(room.lux(z)));
            daylight.put(name, Math.round(room.daylight(z)));
            lamps.put(name, room.brightness(z));
            wants.put(name, room.wantsLight(z));
        }
        ObjectNode energy = t.putObject("energyWh");
        room.energyWh().forEach(energy::put);
        t.put("teacher", teacherPresent(nowS));
        t.put("doorClosed", room.doorClosed());
        return t;
    }

    private boolean teacherPresent(double nowS) {
        Boolean override = teacherOverride;
        return override != null ? override : nowS < options.teacherS();
    }

    /** A lamp's /set: obey it as a Zigbee lamp does, tell the new state, and let the teacher judge it. */
    private void onSet(Mqtt5Publish p) {
        String topic = p.getTopic().toString();
        if (topic.equals(RoomSimOptions.CONTROL_TOPIC)) {
            onControl(p);
            return;
        }
        String device = topic.substring(base.length() + 1, topic.length() - "/set".length());
        JsonNode set;
        try {
            set = JSON.readTree(p.getPayloadAsBytes());
        } catch (IOException e) {
            LOG.warn("{}: '/set' payload is not JSON; ignored", device);
            return;
        }
        synchronized (this) {
            if (!device.endsWith("_lamp") || room.zone(device.substring(0, device.length() - 5)) < 0) {
                LOG.debug("no lamp '{}'; /set ignored", device);
                return;
            }
            int z = room.zone(device.substring(0, device.length() - 5));
            double level = room.brightness(z);
            String state = set.path("state").asText("");
            if (set.has("brightness")) {
                level = Math.max(0, Math.min(MAX_BRIGHTNESS, set.path("brightness").asDouble())) / MAX_BRIGHTNESS;
            }
            if (state.equalsIgnoreCase("OFF")) {
                level = 0;
            } else if (state.equalsIgnoreCase("ON") && level == 0) {
                level = 1;
            } else if (state.equalsIgnoreCase("TOGGLE")) {
                level = room.brightness(z) > 0 ? 0 : 1;
            }
            room.lamp(z, level);
            publishLamp(z);
            double now = clock.nowS();
            if (teacherPresent(now)) {
                boolean good = (level > 0) == room.wantsLight(z);
                judged++;
                if (good) {
                    right++;
                }
                ObjectNode j = JSON.createObjectNode().put("t", now).put("zone", room.zones().get(z))
                        .put("on", level > 0).put("wantsLight", room.wantsLight(z)).put("reward", good ? 1 : -1);
                rewards.add(new Reward(now + TEACHER_DELAY_S, good, j));
            }
        }
    }

    /** The scenario's word: {@code {"teacher": true|false}} sends the teacher in or away. */
    private void onControl(Mqtt5Publish p) {
        try {
            JsonNode c = JSON.readTree(p.getPayloadAsBytes());
            if (c.path("teacher").isBoolean()) {
                teacherOverride = c.path("teacher").booleanValue();
                LOG.info("the teacher is {}", teacherOverride ? "present" : "away");
            }
        } catch (IOException e) {
            LOG.warn("a control message that is not JSON was ignored");
        }
    }

    private void publishLamp(int z) {
        double b = room.brightness(z);
        publish(base + "/" + room.zones().get(z) + "_lamp", b > 0
                ? "{\"state\":\"ON\",\"brightness\":" + Math.round(b * MAX_BRIGHTNESS) + ",\"linkquality\":140}"
                : "{\"state\":\"OFF\",\"brightness\":0,\"linkquality\":140}", false);
    }

    private void publish(String topic, String payload, boolean retain) {
        client.publishWith().topic(topic).payload(utf8(payload)).retain(retain).qos(MqttQos.AT_MOST_ONCE).send();
    }

    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    /** Lamp commands judged by the teacher so far, and how many were right. */
    public synchronized long[] judged() {
        return new long[] {judged, right};
    }

    /** Says the devices are gone (retained, as Zigbee2MQTT does when it stops) and disconnects. */
    @Override
    public void close() {
        clock.close();
        synchronized (this) {
            for (String device : devices()) {
                publish(base + "/" + device + "/availability", "{\"state\":\"offline\"}", true);
            }
            publish(base + "/bridge/state", "{\"state\":\"offline\"}", true);
        }
        try {
            client.disconnect().get(5, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            LOG.debug("disconnect: {}", e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
