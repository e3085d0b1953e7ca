package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.junit.jupiter.api.Test;

class ThreadPlanTest {

    private static final String LINK = "habla-link-robot/main";

    private static ThreadPlan plan(String driver, String methods) throws Exception {
        String json = """
                {"system": "plan-test", "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "%s", "address": "127.0.0.1:9"}],
                 "methods": [%s]}
                """.formatted(driver, methods);
        HablaConfig config = new ConfigLoader(TestMethods.registry()).parse(json);
        return ThreadPlan.of(config, TestMethods.registry());
    }

    private static String method(String id, String type, String layer, String inputs, String more) {
        return """
                {"id": "%s", "type": "%s", "layer": "%s", "inputs": {%s}%s}""".formatted(id, type, layer, inputs, more);
    }

    private static final String LIGHT_CHAIN = String.join(",",
            method("s", "add-one-sensor-light", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
            method("p", "add-one-processing-light", "processing", "\"in\": \"s.out\"", ""),
            method("v", "add-one-virtual-light", "virtual", "\"in\": \"p.out\"", ", \"expose\": {\"port\": 7001}"));

    @Test
    void aLightChainBehindOneConnectionRunsWholeOnThatConnectionsReader() throws Exception {
        ThreadPlan plan = plan("lines-test", LIGHT_CHAIN);
        for (String id : List.of("s", "p", "v")) {
            assertThat(plan.choice(id).inline()).as(id).isTrue();
            assertThat(plan.choice(id).thread()).as(id).isEqualTo(LINK);
        }
        assertThat(plan.shared()).isEqualTo(Map.of(LINK, List.of("s", "p", "v")));
    }

    @Test
    void readingsFromAnInterfaceOfTwoConnectionsComeFromTwoThreads() throws Exception {
        ThreadPlan plan = plan("lines-test-pair", LIGHT_CHAIN);
        assertThat(plan.choice("s").inline()).isFalse();
        assertThat(plan.choice("s").reason()).contains("2 connections");
        assertThat(plan.choice("p").thread()).as("the light ones after it run on its thread").isEqualTo("habla-method-s");
        assertThat(plan.shared()).isEqualTo(Map.of("habla-method-s", List.of("s", "p", "v")));
    }

    @Test
    void aMethodThatIsNotLightKeepsItsThreadAndTheLightOnesAfterItShareIt() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("s", "add-one-sensor", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
                method("p", "add-one-processing-light", "processing", "\"in\": \"s.out\"", ""),
                method("v", "add-one-virtual", "virtual", "\"in\": \"p.out\"", ", \"expose\": {\"port\": 7001}")));
        assertThat(plan.choice("s").inline()).isFalse();
        assertThat(plan.choice("s").reason()).isEqualTo("its type is not light");
        assertThat(plan.choice("p").inline()).isTrue();
        assertThat(plan.choice("p").thread()).isEqualTo("habla-method-s");
        assertThat(plan.choice("v").thread()).isEqualTo("habla-method-v");
    }

    @Test
    void theConfigCanGiveALightMethodAThreadOfItsOwn() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("s", "add-one-sensor-light", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
                method("p", "add-one-processing-light", "processing", "\"in\": \"s.out\"", ", \"thread\": \"own\""),
                method("v", "add-one-virtual-light", "virtual", "\"in\": \"p.out\"", ", \"expose\": {\"port\": 7001}")));
        assertThat(plan.choice("s").thread()).isEqualTo(LINK);
        assertThat(plan.choice("p").inline()).isFalse();
        assertThat(plan.choice("p").reason()).contains("config");
        assertThat(plan.choice("v").thread()).isEqualTo("habla-method-p");
    }

    @Test
    void whatControlClientsOrTheLinkRecordFeedHasMoreThanOneThread() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("c", "command-virtual", "virtual", "\"in\": \"control\"", ", \"expose\": {\"port\": 7001}"),
                method("v", "add-one-virtual-light", "virtual", "\"in\": \"control\"", ", \"expose\": {\"port\": 7002}"),
                method("l", "link-counter-light", "sensors_actuators", "\"link\": \"@robot.link\"", "")));
        assertThat(plan.choice("v").inline()).isFalse();
        assertThat(plan.choice("v").reason()).contains("control clients");
        assertThat(plan.choice("l").inline()).isFalse();
        assertThat(plan.choice("l").reason()).contains("@robot.link");
    }

    @Test
    void aMethodWhoseInputsComeFromTwoThreadsKeepsItsOwn() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("s", "add-one-sensor-light", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
                method("h", "add-one-sensor", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
                method("sum", "sum-light", "processing", "\"a\": \"s.out\", \"b\": \"h.out\"", ""),
                method("both", "sum-light", "processing", "\"a\": \"s.out\", \"b\": \"s.out\"", "")));
        assertThat(plan.choice("sum").inline()).isFalse();
        assertThat(plan.choice("sum").reason()).contains("2 threads").contains(LINK).contains("habla-method-h");
        assertThat(plan.choice("both").thread()).as("two inputs from one thread").isEqualTo(LINK);
    }

    @Test
    void aMethodOnAWorkerOrWritingCommandsKeepsItsOwnAndSoDoWhatAWorkerFeeds() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("s", "add-one-sensor-light", "sensors_actuators", "\"in\": \"@robot.value\"", ""),
                method("w", "add-one-processing-light", "processing", "\"in\": \"s.out\"",
                        ", \"host\": \"127.0.0.1:9\""),
                method("after", "forward-processing-light", "processing", "\"in\": \"w.out\"", ""),
                method("a", "forward-actuator", "sensors_actuators", "\"in\": \"after.out\"",
                        ", \"commands\": {\"out\": \"@robot.motor\"}")));
        assertThat(plan.choice("w").reason()).isEqualTo("it runs on a worker");
        assertThat(plan.choice("after").inline()).isFalse();
        assertThat(plan.choice("after").reason()).contains("worker");
    }

    @Test
    void aLightMethodThatWritesCommandsKeepsItsOwnThread() throws Exception {
        ThreadPlan plan = plan("lines-test", String.join(",",
                method("s", "add-one-sensor-light", "sensors_actuators", "\"in\": \"@robot.value\"",
                        ", \"commands\": {\"out\": \"@robot.motor\"}")));
        assertThat(plan.choice("s").inline()).isFalse();
        assertThat(plan.choice("s").reason()).contains("commands");
    }
}
