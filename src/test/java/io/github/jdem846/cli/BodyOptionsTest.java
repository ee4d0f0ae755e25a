package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --body}/{@code --radius}: a grid whose file names no ellipsoid lies on the body given; a CRS read from the
 * file keeps its own; sun positions by date are refused for bodies other than the Earth.
 */
class BodyOptionsTest {

    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84";

    /** The Luxembourg GridFloat without its .prj: the CRS is only assumed (degrees from the extent). */
    private static Path withoutPrj(Path dir) throws IOException {
        Path flt = dir.resolve("lux.flt");
        Files.copy(Path.of(LUX + ".flt"), flt);
        Files.copy(Path.of(LUX + ".hdr"), dir.resolve("lux.hdr"));
        return flt;
    }

    @Test
    void moonCellsAreMeasuredOnTheMoon(@TempDir Path dir) throws IOException {
        Path flt = withoutPrj(dir);
        CliRun earth = CliRun.of("info", flt.toString(), "--json");
        CliRun moon = CliRun.of("info", flt.toString(), "--json", "--body", "moon");
        assertEquals(0, moon.exitCode(), moon.err());
        // 30″ cells: N–S = R·Δφ on the Moon's sphere (R = 1737.4 km), independent of latitude
        double expectedNs = 1_737_400 * Math.toRadians(30 / 3600.0);
        assertEquals(expectedNs, cellSizeMeters(moon.out(), "y"), 1e-6 * expectedNs);
        // E–W = R·cos φ·Δλ at the centre row's latitude; compare with the Earth's ratio to the N–S size
        double ratioMoon = cellSizeMeters(moon.out(), "x") / cellSizeMeters(moon.out(), "y");
        double ratioEarth = cellSizeMeters(earth.out(), "x") / cellSizeMeters(earth.out(), "y");
        assertEquals(ratioEarth, ratioMoon, 0.01, "cos φ on both bodies (the Earth's flattening changes it a bit)");
        assertTrue(cellSizeMeters(earth.out(), "y") > 900, earth.out());
    }

    @Test
    void radiusGivesASphere(@TempDir Path dir) throws IOException {
        Path flt = withoutPrj(dir);
        CliRun run = CliRun.of("info", flt.toString(), "--json", "--radius", "1000000");
        assertEquals(0, run.exitCode(), run.err());
        assertEquals(1e6 * Math.toRadians(30 / 3600.0), cellSizeMeters(run.out(), "y"), 1e-6);
    }

    @Test
    void aCrsFromTheFileKeepsItsEllipsoid() {
        CliRun earth = CliRun.of("info", LUX + ".flt", "--json");
        CliRun moon = CliRun.of("info", LUX + ".flt", "--json", "--body", "moon");
        assertEquals(0, moon.exitCode(), moon.err());
        assertEquals(cellSizeMeters(earth.out(), "x"), cellSizeMeters(moon.out(), "x"));
        assertEquals(cellSizeMeters(earth.out(), "y"), cellSizeMeters(moon.out(), "y"));
    }

    @Test
    void hillshadeFollowsTheBody(@TempDir Path dir) throws IOException {
        Path flt = withoutPrj(dir);
        Path earth = dir.resolve("earth.tif");
        Path moon = dir.resolve("moon.tif");
        Path moonWithPrj = dir.resolve("moon-prj.tif");
        Path earthWithPrj = dir.resolve("earth-prj.tif");
        assertEquals(0, CliRun.of("hillshade", flt.toString(), "-o", earth.toString()).exitCode());
        assertEquals(0, CliRun.of("hillshade", flt.toString(), "-o", moon.toString(), "--body", "moon").exitCode());
        // the same heights over cells 3.7 times smaller: steeper slopes, another picture
        assertFalse(Files.mismatch(earth, moon) == -1, "the Moon's smaller cells must change the hillshade");
        assertEquals(0, CliRun.of("hillshade", LUX + ".flt", "-o", earthWithPrj.toString()).exitCode());
        assertEquals(0, CliRun.of("hillshade", LUX + ".flt", "-o", moonWithPrj.toString(), "--body", "moon")
                .exitCode());
        assertArrayEquals(Files.readAllBytes(earthWithPrj), Files.readAllBytes(moonWithPrj),
                "a .prj naming WGS 84 wins over --body");
    }

    @Test
    void sunByDateIsForTheEarthOnly(@TempDir Path dir) throws IOException {
        Path flt = withoutPrj(dir);
        Path out = dir.resolve("mars.png");
        CliRun run = CliRun.of("render", flt.toString(), "-o", out.toString(), "--body", "mars", "--sun-time",
                "2024-06-21T12:00Z");
        assertEquals(2, run.exitCode(), "bad usage");
        assertTrue(run.err().contains("Earth only"), run.err());
        assertFalse(Files.exists(out));
        CliRun info = CliRun.of("info", flt.toString(), "--body", "moon", "--sun-time", "2024-06-21T12:00Z");
        assertEquals(2, info.exitCode());
        assertTrue(info.err().contains("Earth only"), info.err());
        CliRun both = CliRun.of("info", flt.toString(), "--body", "moon", "--radius", "5");
        assertEquals(2, both.exitCode());
        assertTrue(both.err().contains("not both"), both.err());
    }

    private static double cellSizeMeters(String json, String axis) {
        Matcher m = Pattern.compile("\"cellSizeMeters\": \\{\"x\": ([0-9.Ee+-]+), \"y\": ([0-9.Ee+-]+)")
                .matcher(json);
        assertTrue(m.find(), json);
        return Double.parseDouble(m.group(axis.equals("x") ? 1 : 2));
    }
}
