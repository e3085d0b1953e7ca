package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.habla.config.ParamsJson;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class SipTranslatorTest {

    private final RecordingSink sink = new RecordingSink();
    private final SipTranslator translator = new SipTranslator(PioneerParams.defaults());

    private void translate(SipBytes b) {
        translator.translate(StandardSip.parse(b.packet()), sink);
    }

    @Test
    void theCapturedSipGivesAllFiveMetresOfSonarAndThirteenVolts() {
        translator.translate(StandardSip.parse(ArcosPacket.of(java.util.Arrays.copyOfRange(
                CapturedSip.wire(), 3, CapturedSip.wire().length - 2))), sink);
        VectorValue sonar = (VectorValue) sink.last("sonar");
        assertThat(sonar.size()).isEqualTo(16);
        for (int i = 0; i < 16; i++) {
            assertThat(sonar.get(i)).isCloseTo(5.0, within(0.001));
        }
        assertThat(((NumberValue) sink.last("battery")).value()).isEqualTo(13.0);
        RecordValue status = (RecordValue) sink.last("status");
        assertThat(status.get("motorsEnabled").booleanValue()).isTrue();
        assertThat(status.get("sonarOn").booleanValue()).isTrue();
        assertThat(status.has("temperatureC")).as("-127 means no reading").isFalse();
    }

    @Test
    void odometryIsInMetresAndRadiansWithTheP2dxFactors() {
        SipBytes b = new SipBytes();
        b.xPos = 1000;
        b.yPos = 500;
        b.thPos = 1024;
        b.leftVel = 200;
        b.rightVel = 300;
        translate(b);
        RecordValue odo = (RecordValue) sink.last("odometry");
        assertThat(odo.number("xM")).isCloseTo(0.840, within(1e-9));
        assertThat(odo.number("yM")).isCloseTo(0.420, within(1e-9));
        assertThat(odo.number("thetaRad")).isCloseTo(Math.PI / 2, within(1e-3));
        assertThat(odo.number("leftMps")).isCloseTo(0.2, within(1e-9));
        assertThat(odo.number("rightMps")).isCloseTo(0.3, within(1e-9));
        assertThat(odo.number("vMps")).isCloseTo(0.25, within(1e-9));
        assertThat(odo.number("wRadps")).as("(R-L)/2 x DiffConvFactor").isCloseTo(50 * 0.0056, within(1e-9));
    }

    @Test
    void theRotationalVelocityFieldWinsWhenTheSipCarriesIt() {
        SipBytes b = new SipBytes();
        b.tail = true;
        b.leftVel = -93;
        b.rightVel = 93;
        b.rotVel = 300;
        translate(b);
        RecordValue odo = (RecordValue) sink.last("odometry");
        assertThat(odo.number("wRadps")).isCloseTo(Math.toRadians(30), within(1e-9));
    }

    @Test
    void odometryStaysContinuousAcrossTheRollOver() {
        SipBytes b = new SipBytes();
        b.xPos = 16000;
        translate(b);
        b.xPos = 32000;
        translate(b);
        b.xPos = 200;
        translate(b);
        RecordValue odo = (RecordValue) sink.last("odometry");
        assertThat(odo.number("xM")).as("32768 + 200 units of 0.84 mm").isCloseTo(32968 * 0.00084, within(1e-9));
    }

    @Test
    void headingIsNormalisedIntoMinusPiToPi() {
        SipBytes b = new SipBytes();
        b.thPos = 3072;
        translate(b);
        assertThat(((RecordValue) sink.last("odometry")).number("thetaRad")).isCloseTo(-Math.PI / 2, within(1e-3));
        assertThat(SipTranslator.normalise(-Math.PI)).isEqualTo(Math.PI);
        assertThat(SipTranslator.normalise(3 * Math.PI)).isCloseTo(Math.PI, within(1e-12));
    }

    @Test
    void bumpersAndStallsBecomeRecordsOfBooleans() {
        SipBytes b = new SipBytes();
        b.stallAndBumpers = 0x0100 | (1 << 10) | (1 << 1);
        translate(b);
        RecordValue bumpers = (RecordValue) sink.last("bumpers");
        assertThat(bumpers.get("front").toString()).isEqualTo("[false,true,false,false,false]");
        assertThat(bumpers.get("rear").toString()).isEqualTo("[true,false,false,false,false]");
        assertThat(bumpers.get("frontHit").booleanValue()).isTrue();
        assertThat(bumpers.get("rearHit").booleanValue()).isTrue();
        RecordValue stall = (RecordValue) sink.last("stall");
        assertThat(stall.get("left").booleanValue()).isFalse();
        assertThat(stall.get("right").booleanValue()).isTrue();
    }

    @Test
    void sonarIsEmittedOnlyWhenASipCarriesReadingsAndTheRingIsComplete() {
        SipBytes b = new SipBytes();
        for (int i = 0; i < 8; i++) {
            b.sonar(i, 1000);
        }
        translate(b);
        assertThat(sink.on("sonar")).isEmpty();
        SipBytes rest = new SipBytes();
        for (int i = 8; i < 16; i++) {
            rest.sonar(i, 2000);
        }
        translate(rest);
        assertThat(sink.on("sonar")).hasSize(1);
        translate(new SipBytes());
        assertThat(sink.on("sonar")).hasSize(1);
        VectorValue ranges = (VectorValue) sink.last("sonar");
        assertThat(ranges.get(0)).isCloseTo(0.268, within(1e-9));
        assertThat(ranges.get(15)).isCloseTo(0.536, within(1e-9));
    }

    @Test
    void aP3dxNeedsBothConversionFactorsForTrueMetresOfSonarAndOdometry() throws Exception {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        PioneerParams p3dx = ParamsJson.of(PioneerParams.class, "{\"distConvFactor\": 0.485, \"rangeConvFactor\": 1.0}");
        PioneerParams distOnly = ParamsJson.of(PioneerParams.class, "{\"distConvFactor\": 0.485}");
        // An ARCOS P3-DX (and AMRISim's p3dx) reports sonar in millimetres and positions in 0.485 mm units.
        SipBytes b = new SipBytes();
        b.xPos = 2000;
        for (int i = 0; i < 16; i++) {
            b.sonar(i, 1500);
        }

        RecordingSink right = new RecordingSink();
        new SipTranslator(p3dx).translate(StandardSip.parse(b.packet()), right);
        RecordingSink wrong = new RecordingSink();
        new SipTranslator(distOnly).translate(StandardSip.parse(b.packet()), wrong);

        assertThat(((VectorValue) right.last("sonar")).get(3)).isCloseTo(1.5, within(1e-9));
        assertThat(((RecordValue) right.last("odometry")).number("xM")).isCloseTo(0.970, within(1e-9));
        assertThat(((VectorValue) wrong.last("sonar")).get(3)).as("the P2DX's 0.268 mm units: 0.268 × true")
                .isCloseTo(1.5 * 0.268, within(1e-9));
    }

    @Test
    void aSonarIndexTheRobotDoesNotHaveIsCountedAsMalformed() {
        translate(new SipBytes().sonar(20, 100).sonar(0, 100));
        assertThat(sink.malformed()).singleElement().asString().contains("sonar index 20");
    }

    @Test
    void theStatusNamesTheRobotFromTheHandshake() {
        translator.identity(new RobotIdentity("AMRISim", "Pioneer", "p2dx"));
        translate(new SipBytes());
        RecordValue status = (RecordValue) sink.last("status");
        assertThat(status.text("robotName")).isEqualTo("AMRISim");
        assertThat(status.text("robotSubclass")).isEqualTo("p2dx");
    }

    @Test
    void theStallBumperAndStatusRecordsAreWrittenAsTheDriverDocumentsThem() {
        SipBytes b = new SipBytes();
        b.type = StandardSip.TYPE_MOVING;
        b.stallAndBumpers = 0x0001 | (1 << 9) | (1 << 5);
        b.flags = 0x21;
        translator.identity(new RobotIdentity("AMRISim", "Pioneer", "p2dx"));
        translator.ignoredPackets(3);
        translate(b);
        assertThat(json("stall")).isEqualTo("{\"left\":true,\"right\":false}");
        assertThat(json("bumpers")).isEqualTo("{\"front\":[true,false,false,false,false],"
                + "\"rear\":[false,false,false,false,true],\"frontHit\":true,\"rearHit\":true}");
        assertThat(json("status")).isEqualTo("{\"motorsEnabled\":true,\"sonarOn\":false,\"stopButton\":true,"
                + "\"eStall\":false,\"moving\":true,\"flags\":33,\"robotName\":\"AMRISim\",\"robotClass\":\"Pioneer\","
                + "\"robotSubclass\":\"p2dx\",\"ignoredPackets\":3}");

        b.tail = true;
        b.stallAndBumpers = 0;
        translate(b);
        assertThat(json("bumpers")).isEqualTo("{\"front\":[false,false,false,false,false],"
                + "\"rear\":[false,false,false,false,false],\"frontHit\":false,\"rearHit\":false}");
        assertThat(json("status")).as("the newer firmware's tail; -127 is no temperature").isEqualTo(
                "{\"motorsEnabled\":true,\"sonarOn\":false,\"stopButton\":true,\"eStall\":false,\"moving\":true,"
                + "\"flags\":33,\"robotName\":\"AMRISim\",\"robotClass\":\"Pioneer\",\"robotSubclass\":\"p2dx\","
                + "\"ignoredPackets\":3,\"chargeState\":0,\"faultFlags\":0,\"stateOfChargePct\":77}");
        b.temperature = 31;
        translate(b);
        assertThat(json("status")).endsWith("\"chargeState\":0,\"faultFlags\":0,\"temperatureC\":31,"
                + "\"stateOfChargePct\":77}");
        assertThat(((RecordValue) sink.last("status")).form(StatusReading.class)).as("typed inside the daemon")
                .hasValueSatisfying(s -> assertThat(s.temperatureC()).isEqualTo(31));
        assertThat(((RecordValue) sink.last("stall")).form(StallReading.class)).contains(new StallReading(false, false));
        assertThat(((RecordValue) sink.last("bumpers")).form(BumperReading.class)).isPresent();
    }

    private String json(String channel) {
        return ((RecordValue) sink.last(channel)).jsonView().toString();
    }
}
