package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The rendering subcommands end to end, in-process, on real DEMs. */
class RenderCommandsTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";
    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final String VOLCANO = "testdata/dem/maungawhau-volcano_10m_nztm-approx.tif";

    @TempDir
    Path dir;

    @Test
    void renderWithoutFileDrawsTheBundledSample() throws IOException {
        Path out = dir.resolve("sample.png");
        CliRun run = CliRun.of("render", "-o", out.toString());
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(600, img.getWidth());
        assertEquals(400, img.getHeight());
        assertEquals(0xFF, img.getRGB(300, 200) >>> 24);
        assertNoStrayFiles(out);
    }

    @Test
    void verbosePrintsThePhaseTimesAndQuietRunsDoNot() {
        for (String[] command : new String[][] {{"hillshade", LUX}, {"tint", LUX}, {"render", LUX},
            {"shadows", LUX}}) {
            Path out = dir.resolve(command[0] + ".png");
            CliRun verbose = CliRun.of(command[0], command[1], "-o", out.toString(), "--verbose");
            assertEquals(0, verbose.exitCode(), verbose.err());
            assertTrue(verbose.err().matches("(?s).*jdem846: timing: start-up -?\\d+ ms, read \\d+ ms, "
                    + command[0] + " \\d+ ms, write \\d+ ms; total \\d+ ms.*"), verbose.err());
            CliRun quiet = CliRun.of(command[0], command[1], "-o", out.toString());
            assertEquals(0, quiet.exitCode(), quiet.err());
            assertFalse(quiet.err().contains("timing"), quiet.err());
        }
    }

    @Test
    void targetWidthKeepsTheAspectRatio() throws IOException {
        Path out = dir.resolve("small.png");
        CliRun run = CliRun.of("render", BT, "-o", out.toString(), "--width", "300");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(300, img.getWidth());
        assertEquals(Math.round(643 * 300.0 / 1197), img.getHeight());
    }

    @Test
    void hornHillshadeEqualsGdaldem() throws IOException {
        // testdata/golden/hillshade/README.md: gdaldem hillshade -compute_edges -az 1000000 -alt 89.99 (volcano)
        Path out = dir.resolve("horn.png");
        CliRun run = CliRun.of("hillshade", VOLCANO, "-o", out.toString(), "--method", "horn", "--sun-azimuth",
                "1000000", "--sun-elevation", "89.99");
        assertEquals(0, run.exitCode(), run.err());
        assertSameGray(Path.of("testdata/golden/hillshade/vo_horn_az1e6_alt89.99.png"), out, 1);
        Path multi = dir.resolve("multi.png");
        run = CliRun.of("hillshade", LUX, "-o", multi.toString(), "--multidirectional", "-s", "111120", "-z", "5",
                "--sun-elevation", "45");
        assertEquals(0, run.exitCode(), run.err());
        assertSameGray(Path.of("testdata/golden/hillshade/lux_multidir_s111120_alt45_z5.png"), multi, 1);
    }

    @Test
    void tintWithAColourFileEqualsGdaldemColorRelief() throws IOException {
        Path out = dir.resolve("tint.png");
        CliRun run = CliRun.of("tint", LUX, "-o", out.toString(), "--tint",
                "testdata/golden/tint/colors/table2_percent.txt");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage ours = ImageIO.read(out.toFile());
        BufferedImage gdal = ImageIO.read(Path.of("testdata/golden/tint/luxembourg_table2.png").toFile());
        int maxDiff = 0;
        for (int y = 0; y < gdal.getHeight(); y++) {
            for (int x = 0; x < gdal.getWidth(); x++) {
                int a = ours.getRGB(x, y);
                int b = gdal.getRGB(x, y);
                if ((b >>> 24) == 0) {
                    assertEquals(0, a >>> 24, "no-data stays transparent at " + x + "," + y);
                    continue;
                }
                for (int s = 0; s < 32; s += 8) {
                    maxDiff = Math.max(maxDiff, Math.abs(((a >>> s) & 0xff) - ((b >>> s) & 0xff)));
                }
            }
        }
        assertTrue(maxDiff <= 1, "max channel difference " + maxDiff);
    }

    @Test
    void shadowMaskIsBinaryAndNoDataIsLit() throws IOException {
        Path out = dir.resolve("mask.png");
        CliRun run = CliRun.of("shadows", LUX, "-o", out.toString(), "--algorithm", "sweep", "--sun-azimuth=-720",
                "--sun-elevation", "3");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage mask = ImageIO.read(out.toFile());
        BufferedImage lux = ImageIO.read(Path.of("testdata/golden/tint/luxembourg_table2.png").toFile());
        int shadowed = 0;
        for (int y = 0; y < mask.getHeight(); y++) {
            for (int x = 0; x < mask.getWidth(); x++) {
                int v = mask.getRaster().getSample(x, y, 0);
                assertTrue(v == 0 || v == 255, "hard mask value " + v);
                if ((lux.getRGB(x, y) >>> 24) == 0) {
                    assertEquals(0, v, "no-data cell " + x + "," + y);
                }
                shadowed += v == 255 ? 1 : 0;
            }
        }
        assertTrue(shadowed > 0, "a 3° sun casts shadows in Luxembourg's valleys");
    }

    @Test
    void aWindowedRenderEqualsTheSameWindowOfTheFullRender() throws IOException {
        for (String algorithm : new String[] {"march", "sweep"}) {
            Path full = dir.resolve(algorithm + "-full.png");
            Path part = dir.resolve(algorithm + "-part.png");
            String[] common = {"--shadows", algorithm, "--sun-azimuth", "250", "--sun-elevation", "6"};
            assertEquals(0, CliRun.of(concat(new String[] {"render", BT, "-o", full.toString()}, common)).exitCode());
            CliRun run = CliRun.of(concat(new String[] {"render", BT, "-o", part.toString(), "--window",
                "cells:500,200,160,120"}, common));
            assertEquals(0, run.exitCode(), run.err());
            BufferedImage a = ImageIO.read(full.toFile()).getSubimage(500, 200, 160, 120);
            BufferedImage b = ImageIO.read(part.toFile());
            assertEquals(160, b.getWidth());
            assertEquals(120, b.getHeight());
            assertArrayEquals(a.getRGB(0, 0, 160, 120, null, 0, 160), b.getRGB(0, 0, 160, 120, null, 0, 160),
                    algorithm);
        }
    }

    @Test
    void worldFileAndPrjPlaceTheImage() throws IOException {
        Path out = dir.resolve("placed.png");
        CliRun run = CliRun.of("render", BT, "-o", out.toString(), "--world-file", "--scale", "0.5");
        assertEquals(0, run.exitCode(), run.err());
        String[] pgw = Files.readString(dir.resolve("placed.pgw")).trim().split("\\R");
        double pixel = Double.parseDouble(pgw[0]);
        // 1197 cells of 30 m in round(1197 × 0.5) = 599 pixels
        assertEquals(1197 * 30.0 / 599, pixel, 1e-9);
        assertEquals(376313.6554542635 + pixel / 2, Double.parseDouble(pgw[4]), 1e-6);
        assertTrue(Files.readString(dir.resolve("placed.prj")).contains("UTM"));
    }

    @Test
    void badInputGivesOneLineAndNoOutput() {
        Path out = dir.resolve("never.png");
        CliRun missing = CliRun.of("render", "no/such/dem.tif", "-o", out.toString());
        assertEquals(1, missing.exitCode());
        assertTrue(missing.err().contains("no/such/dem.tif"), missing.err());
        assertFalse(missing.err().contains("\tat "), "no stack trace: " + missing.err());
        // an unknown ramp, a window outside the grid and an angle out of range are bad usage (exit 2)
        CliRun badTint = CliRun.of("render", BT, "-o", out.toString(), "--tint", "rainbowz");
        assertEquals(2, badTint.exitCode());
        assertTrue(badTint.err().contains("hypsometric"), "lists the ramps: " + badTint.err());
        CliRun badWindow = CliRun.of("render", BT, "-o", out.toString(), "--window", "cells:2000,0,10,10");
        assertEquals(2, badWindow.exitCode());
        assertTrue(badWindow.err().contains("1197"), badWindow.err());
        CliRun badSun = CliRun.of("render", BT, "-o", out.toString(), "--sun-elevation", "95");
        assertEquals(2, badSun.exitCode());
        assertTrue(badSun.err().contains("-90 and 90"), badSun.err());
        CliRun badExt = CliRun.of("render", BT, "-o", dir.resolve("x.gif").toString());
        assertEquals(2, badExt.exitCode(), "an unknown extension is bad usage");
        assertTrue(badExt.err().contains(".png") && badExt.err().contains("--output"), badExt.err());
        CliRun usage = CliRun.of("render", BT);
        assertEquals(2, usage.exitCode());
        assertFalse(Files.exists(out));
        assertNoStrayFiles(out);
    }

    @Test
    void sunByTimeNeedsAPlaceWhenTheCrsIsUnknown() throws IOException {
        Path flt = dir.resolve("local.flt");
        Files.write(flt, new byte[4 * 4 * 4]);
        Files.writeString(dir.resolve("local.hdr"), "ncols 4\nnrows 4\nxllcorner 1000\nyllcorner 1000\n"
                + "cellsize 10\nbyteorder LSBFIRST\n");
        Path out = dir.resolve("t.png");
        CliRun run = CliRun.of("render", flt.toString(), "-o", out.toString(), "--sun-time",
                "2024-06-21T12:00+02:00");
        assertEquals(1, run.exitCode());
        assertTrue(run.err().contains("--sun-at"), run.err());
        CliRun ok = CliRun.of("render", flt.toString(), "-o", out.toString(), "--sun-time",
                "2024-06-21T13:36+02:00", "--sun-at", "49.6,6.1");
        assertEquals(0, ok.exitCode(), ok.err());
        assertTrue(ok.err().contains("elevation 63."), ok.err()); // solar noon at the solstice, 49.6° N: 90 − 49.6 + 23.44
    }

    private static String[] concat(String[] a, String[] b) {
        String[] r = new String[a.length + b.length];
        System.arraycopy(a, 0, r, 0, a.length);
        System.arraycopy(b, 0, r, a.length, b.length);
        return r;
    }

    private void assertNoStrayFiles(Path out) {
        try (Stream<Path> files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().startsWith(".")),
                    "temporary files left in " + dir);
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    private static void assertSameGray(Path golden, Path ours, int tolerance) throws IOException {
        BufferedImage g = ImageIO.read(golden.toFile());
        BufferedImage o = ImageIO.read(ours.toFile());
        assertEquals(g.getWidth(), o.getWidth());
        assertEquals(g.getHeight(), o.getHeight());
        for (int y = 0; y < g.getHeight(); y++) {
            for (int x = 0; x < g.getWidth(); x++) {
                int a = g.getRaster().getSample(x, y, 0);
                int b = o.getRaster().getSample(x, y, 0);
                assertTrue(Math.abs(a - b) <= tolerance, "pixel " + x + "," + y + ": gdaldem " + a + ", ours " + b);
            }
        }
    }
}
