package org.habla.sim.aibo;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Numbers of a posture come out as C's printf("%g") prints the same float (expected values from glibc's printf). */
class PrintfGTest {

    @ParameterizedTest(name = "{0}f prints as {1}")
    @CsvSource(delimiter = '|', textBlock = """
        1500          | 1500
        0.5235988     | 0.523599
        1e-5          | 1e-05
        123456789     | 1.23457e+08
        0.0001        | 0.0001
        100000        | 100000
        1e6           | 1e+06
        -2.5          | -2.5
        0.00012345678 | 0.000123457
        999999.5      | 1e+06
        -0.0          | -0
        0             | 0
        0.139         | 0.139
        3.185         | 3.185
        12345.678     | 12345.7
        1e-10         | 1e-10
        0.1           | 0.1
        0.6666667     | 0.666667
        -9.81         | -9.81
        """)
    void aFloatPrintsAsCsPercentG(float value, String printed) {
        assertThat(PrintfG.of(value)).isEqualTo(printed);
    }

    @ParameterizedTest(name = "{0} prints as {1}")
    @CsvSource(delimiter = '|', textBlock = """
        NaN       | nan
        Infinity  | inf
        -Infinity | -inf
        """)
    void nonFiniteNumbersPrintAsGlibcDoes(double value, String printed) {
        assertThat(PrintfG.of(value)).isEqualTo(printed);
    }
}
