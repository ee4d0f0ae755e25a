package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --memory}: a picture larger than the budget is rendered in tiles, says so in one note, and is the same
 * file as without the option.
 */
class MemoryOptionTest {

    private static final String JACKSBORO = "testdata/dem/jacksboro_srtm3s_wgs84.flt";

    @TempDir
    Path dir;

    @Test
    void aSmallBudgetRendersTheSameFileInTiles() throws IOException {
        Path whole = dir.resolve("whole.tif");
        Path tiled = dir.resolve("tiled.tif");
        String[] common = {"render", JACKSBORO, "--shadows", "sweep", "--sun-elevation", "8", "--threads", "2"};
        CliRun a = CliRun.of(concat(common, "-o", whole.toString()));
        CliRun b = CliRun.of(concat(common, "-o", tiled.toString(), "--memory", "400k"));
        assertEquals(0, a.exitCode(), a.err());
        assertEquals(0, b.exitCode(), b.err());
        assertEquals("", a.err().strip());
        assertTrue(b.err().strip().matches("jdem846: note: the 403×344 picture needs \\d+ MiB at once, more than"
                + " the memory budget of 400 KiB: rendering it in \\d+ × \\d+ tiles of up to \\d+×\\d+ pixels"),
                b.err());
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(tiled));
    }

    @Test
    void aCloudOptimizedGeoTiffInTilesIsTheSameFile() throws IOException {
        Path whole = dir.resolve("whole-cog.tif");
        Path tiled = dir.resolve("tiled-cog.tif");
        String[] common = {"hillshade", JACKSBORO, "--cog", "-q", "--threads", "2"};
        assertEquals(0, CliRun.of(concat(common, "-o", whole.toString())).exitCode());
        assertEquals(0, CliRun.of(concat(common, "-o", tiled.toString(), "--memory", "100k")).exitCode());
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(tiled));
    }

    private static String[] concat(String[] a, String... b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
