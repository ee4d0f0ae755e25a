package io.github.jdem846.geo;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import java.nio.charset.StandardCharsets;

/**
 * Fuzz test of WKT sniffing and parsing ({@link CrsResolver#fromWkt}: the common CRSs recognised without Apache
 * SIS, the rest parsed by SIS): a CRS, or the documented IllegalArgumentException raised by CrsResolver itself.
 * The normal test run replays {@code src/test/resources/io/github/jdem846/geo/CrsResolverFuzzTestInputs/wkt/};
 * {@code -Pfuzz} fuzzes (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class CrsResolverFuzzTest {

    @FuzzTest
    void wkt(byte[] data) {
        String text = new String(data, StandardCharsets.UTF_8);
        try {
            if (CrsResolver.fromWkt(text) == null) {
                throw new AssertionError("no CRS");
            }
        } catch (IllegalArgumentException e) {
            String m = e.getMessage();
            if (m == null || !(m.startsWith("not a CRS in WKT") || m.startsWith("the WKT text is empty"))) {
                throw e; // not CrsResolver's own refusal
            }
        }
    }
}
