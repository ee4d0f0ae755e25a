package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SolarCalculator;
import io.github.jdem846.sun.SunPosition;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class InfoSunTest {

    @Test
    void infoGivesTheSunAtTheGridCentre() {
        CliRun run = CliRun.of("info", "testdata/dem/luxembourg_srtm30s_wgs84.tif", "--json", "--sun-time",
                "2024-06-21T05:30+02:00");
        assertEquals(0, run.exitCode(), run.err());
        // Centre of the 95×90 grid of 30″ cells from 5.741667° E, 50.191667° N: (47.5, 45) cells in.
        double lon = 5.741666666666666 + 47.5 / 120;
        double lat = 49.44166666666666 + 90 / 120.0 - 45.0 / 120;
        SunPosition expected = SolarCalculator.position(ZonedDateTime.parse("2024-06-21T05:30+02:00"),
                new LatLon(lat, lon), Observer.SEA_LEVEL);
        assertEquals(expected.azimuthDegrees(), number(run.out(), "azimuth"), 1e-6);
        assertEquals(expected.elevationDegrees(), number(run.out(), "elevation"), 1e-6);
        assertTrue(number(run.out(), "elevation") < 1, "just after sunrise");
    }

    @Test
    void unknownCrsNeedsAPlace(@TempDir Path dir) throws IOException {
        Path flt = dir.resolve("local.flt");
        Files.write(flt, new byte[2 * 2 * 4]);
        Files.writeString(dir.resolve("local.hdr"), "ncols 2\nnrows 2\nxllcorner 5000\nyllcorner 5000\n"
                + "cellsize 10\nbyteorder LSBFIRST\n");
        CliRun run = CliRun.of("info", flt.toString(), "--sun-time", "2024-06-21T12:00Z");
        assertEquals(1, run.exitCode());
        assertTrue(run.err().contains("--sun-at"), run.err());
        CliRun placed = CliRun.of("info", flt.toString(), "--sun-time", "2024-06-21T12:00Z", "--sun-at", "0,0");
        assertEquals(0, placed.exitCode(), placed.err());
        assertTrue(placed.out().contains("Sun:"), placed.out());
    }

    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\": (-?[0-9.Ee+-]+)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return Double.parseDouble(m.group(1));
    }
}
