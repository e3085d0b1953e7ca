package org.habla.dist;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.assertj.core.api.Assertions.assertThat;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.core.importer.Location;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Which way HABLA's modules depend, checked on their classes (tests left out): the engine (habla-core) imports none
 * of the modules built on it; methods and drivers know only the engine; the monitor and the recording know only the
 * engine and not each other; the command line knows neither a method, nor a driver, nor the simulator; nothing
 * imports the simulator or the benchmarks; Jetty is the monitor's alone and zstd the recording's; and no two
 * packages import each other, round about or directly.
 */
class ArchitectureTest {

    /** The engine's packages: what every daemon and worker runs. */
    static final String[] ENGINE = {"org.habla.sample..", "org.habla.method..", "org.habla.plugin..",
        "org.habla.driver..", "org.habla.bridge..", "org.habla.config..", "org.habla.graph..", "org.habla.net..",
        "org.habla.security..", "org.habla.worker..", "org.habla.daemon..", "org.habla.status..",
        "org.habla.command.."};
    static final String[] METHODS = {"org.habla.methods.."};
    static final String[] DRIVERS = {"org.habla.drivers.."};
    static final String[] RECORDING = {"org.habla.recording..", "org.habla.replay.."};
    static final String[] MONITOR = {"org.habla.monitor.."};
    static final String[] CLI = {"org.habla.cli..", "org.habla.draw.."};
    static final String[] SIM = {"org.habla.sim.."};
    static final String[] BENCH = {"org.habla.bench.."};

    private static JavaClasses classes;

    @BeforeAll
    static void importEveryModulesClasses() {
        classes = new ClassFileImporter().withImportOption(ArchitectureTest::mainClass).importPackages("org.habla");
    }

    /** A module's own classes: no test class, from a module's test folder or its test jar. */
    private static boolean mainClass(Location location) {
        return ImportOption.Predefined.DO_NOT_INCLUDE_TESTS.includes(location) && !location.contains("-tests.jar");
    }

    @Test
    void everyModuleIsImported() {
        for (String module : new String[] {"org.habla.graph", "org.habla.methods.speech", "org.habla.drivers.pioneer",
            "org.habla.recording", "org.habla.monitor", "org.habla.cli", "org.habla.sim.pioneer", "org.habla.bench"}) {
            assertThat(classes.containPackage(module)).as(module).isTrue();
        }
        assertThat(classes.stream().filter(c -> c.getSimpleName().endsWith("Test"))).isEmpty();
    }

    @Test
    void eachLayerImportsOnlyTheLayersBelowIt() {
        layeredArchitecture().consideringOnlyDependenciesInLayers().withOptionalLayers(true)
                .layer("engine").definedBy(ENGINE)
                .layer("methods").definedBy(METHODS)
                .layer("drivers").definedBy(DRIVERS)
                .layer("recording").definedBy(RECORDING)
                .layer("monitor").definedBy(MONITOR)
                .layer("cli").definedBy(CLI)
                .layer("sim").definedBy(SIM)
                .layer("bench").definedBy(BENCH)
                .whereLayer("engine").mayOnlyBeAccessedByLayers("methods", "drivers", "recording", "monitor", "cli",
                        "sim", "bench")
                .whereLayer("methods").mayOnlyBeAccessedByLayers("bench")
                .whereLayer("drivers").mayOnlyBeAccessedByLayers("bench")
                .whereLayer("recording").mayOnlyBeAccessedByLayers("cli", "bench")
                .whereLayer("monitor").mayOnlyBeAccessedByLayers("cli", "bench")
                .whereLayer("cli").mayOnlyBeAccessedByLayers("sim", "bench")
                .whereLayer("sim").mayOnlyBeAccessedByLayers("bench")
                .whereLayer("bench").mayNotBeAccessedByAnyLayer()
                .check(classes);
    }

    @Test
    void theEngineImportsNoModuleBuiltOnIt() {
        noClasses().that().resideInAnyPackage(ENGINE).should().dependOnClassesThat()
                .resideInAnyPackage(concat(METHODS, DRIVERS, RECORDING, MONITOR, CLI, SIM, BENCH))
                .check(classes);
    }

    @Test
    void methodsAndDriversImportNeitherTheCommandLineNorTheMonitorNorTheRecording() {
        noClasses().that().resideInAnyPackage(concat(METHODS, DRIVERS)).should().dependOnClassesThat()
                .resideInAnyPackage(concat(CLI, MONITOR, RECORDING, SIM, BENCH))
                .check(classes);
    }

    @Test
    void jettyIsTheMonitorsAloneAndZstdTheRecordingsAlone() {
        noClasses().that().resideOutsideOfPackages(MONITOR).should().dependOnClassesThat()
                .resideInAnyPackage("org.eclipse.jetty..").check(classes);
        noClasses().that().resideOutsideOfPackages(RECORDING).should().dependOnClassesThat()
                .resideInAnyPackage("com.github.luben..").check(classes);
    }

    @Test
    void noPackagesDependOnEachOtherInACycle() {
        slices().matching("org.habla.(**)").should().beFreeOfCycles().check(classes);
    }

    private static String[] concat(String[]... groups) {
        return java.util.Arrays.stream(groups).flatMap(java.util.Arrays::stream).toArray(String[]::new);
    }
}
