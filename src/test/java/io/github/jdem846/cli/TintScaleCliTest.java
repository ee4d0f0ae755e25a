package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --tint-scale} on the command line: it changes the tint of a real DEM, and misuse is exit 2. */
class TintScaleCliTest {

    private static final String DEM = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path tmp;

    @Test
    void aScaleChangesTheTintAndLinearIsTheDefault() throws Exception {
        Path plain = tmp.resolve("plain.png");
        Path linear = tmp.resolve("linear.png");
        Path cubic = tmp.resolve("cubic.png");
        assertEquals(0, CliRun.of("tint", DEM, "-o", plain.toString(), "--width", "200").exitCode());
        assertEquals(0, CliRun.of("tint", DEM, "-o", linear.toString(), "--width", "200", "--tint-scale", "LINEAR")
                .exitCode());
        assertEquals(0, CliRun.of("tint", DEM, "-o", cubic.toString(), "--width", "200", "--tint-scale", "cubic")
                .exitCode());
        assertEquals(-1, Files.mismatch(plain, linear));
        assertNotEquals(-1, Files.mismatch(plain, cubic));
    }

    @Test
    void aRampInMetresOrAnUnknownScaleIsBadUsage() {
        Path out = tmp.resolve("x.png");
        CliRun metres = CliRun.of("render", DEM, "-o", out.toString(), "--tint", "etopo1", "--tint-scale", "cubic");
        assertEquals(2, metres.exitCode(), metres.err());
        assertTrue(metres.err().contains("etopo1") && metres.err().contains("percent"), metres.err());
        CliRun unknown = CliRun.of("render", DEM, "-o", out.toString(), "--tint-scale", "cubix");
        assertEquals(2, unknown.exitCode(), unknown.err());
        assertTrue(unknown.err().toLowerCase().contains("logarithmic"), unknown.err());
        assertFalse(Files.exists(out));
    }
}
