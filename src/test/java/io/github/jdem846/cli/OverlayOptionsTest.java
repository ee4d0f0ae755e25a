package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code render --overlay}: a good file changes the picture, no overlay leaves it as it was; a bad file is one line
 * naming it, exit 1, and no picture; a bad style is bad usage, exit 2. With {@code --projection} the projected
 * picture gets the shapes; {@code tiles} takes {@code --overlay} as render does; the gray products refuse it as bad
 * usage, saying what to use instead.
 */
class OverlayOptionsTest {

    private static final String DEM = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
    private static final String SHAPES = "testdata/overlay/jacksboro_test_shapes.geojson";

    @TempDir
    Path dir;

    private CliRun render(Path out, String... extra) {
        String[] base = {"render", DEM, "-o", out.toString(), "-q", "--threads=2"};
        String[] all = Arrays.copyOf(base, base.length + extra.length);
        System.arraycopy(extra, 0, all, base.length, extra.length);
        return CliRun.of(all);
    }

    @Test
    void anOverlayChangesThePictureAndStylesApply() throws IOException {
        Path plain = dir.resolve("plain.png");
        Path red = dir.resolve("red.png");
        Path blue = dir.resolve("blue.png");
        assertEquals(0, render(plain).exitCode());
        CliRun r = render(red, "--overlay", SHAPES);
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(0, render(blue, "--overlay", SHAPES + ":color=blue,width=3").exitCode());
        byte[] p = Files.readAllBytes(plain);
        assertFalse(Arrays.equals(p, Files.readAllBytes(red)));
        assertFalse(Arrays.equals(Files.readAllBytes(red), Files.readAllBytes(blue)));
    }

    @Test
    void aWindowGetsTheOverlayWhereTheWholePictureHasIt() throws IOException {
        String styled = SHAPES + ":color=#ff0000,width=1,fill=#0000ff80,radius=4";
        Path whole = dir.resolve("whole.png");
        Path window = dir.resolve("window.png");
        assertEquals(0, render(whole, "--overlay", styled).exitCode());
        assertEquals(0, render(window, "--overlay", styled, "--window", "cells:40,90,300,200").exitCode());
        java.awt.image.BufferedImage w = javax.imageio.ImageIO.read(whole.toFile());
        java.awt.image.BufferedImage part = javax.imageio.ImageIO.read(window.toFile());
        assertEquals(300, part.getWidth());
        for (int y = 0; y < part.getHeight(); y++) {
            for (int x = 0; x < part.getWidth(); x++) {
                assertEquals(w.getRGB(x + 40, y + 90), part.getRGB(x, y), "pixel " + x + "," + y);
            }
        }
        assertEquals(0xffff0000, part.getRGB(160, 10), "the line on row 100 is row 10 of the window");
    }

    @Test
    void badFilesAreOneLineNamingTheFileExitOneAndNoPicture() throws IOException {
        Path garbage = dir.resolve("garbage.geojson");
        Files.writeString(garbage, "{\"type\": \"FeatureCollection\", \"features\": [ {");
        Path truncated = dir.resolve("truncated.shp");
        byte[] shp = Files.readAllBytes(Path.of("testdata/overlay/jacksboro_test_shapes_lines.shp"));
        Files.write(truncated, Arrays.copyOf(shp, shp.length - 20));
        Path notShp = dir.resolve("text.shp");
        Files.writeString(notShp, "x".repeat(200));
        Path kml = dir.resolve("shapes.kml");
        Files.writeString(kml, "<kml/>");
        for (Path bad : new Path[] {garbage, truncated, notShp, kml, dir.resolve("missing.geojson")}) {
            Path out = dir.resolve("out.png");
            CliRun r = render(out, "--overlay", bad.toString());
            assertEquals(1, r.exitCode(), bad + ": " + r.err());
            assertEquals(1, r.err().strip().lines().count(), r.err());
            assertTrue(r.err().startsWith("jdem846: " + bad), r.err());
            assertFalse(r.err().contains("Exception"), r.err());
            assertFalse(Files.exists(out), "no picture for " + bad);
        }
    }

    @Test
    void aBadStyleIsBadUsage() {
        Path out = dir.resolve("out.png");
        CliRun style = render(out, "--overlay", SHAPES + ":colour=nope");
        assertEquals(2, style.exitCode(), style.err());
        assertTrue(style.err().contains("colour 'nope'"), style.err());
        CliRun projected = render(out, "--overlay", SHAPES + ":width=-1", "--projection", "mollweide");
        assertEquals(2, projected.exitCode(), projected.err());
        CliRun tiles = CliRun.of("tiles", DEM, "--zoom", "10", "-o", dir.resolve("tiles").toString(), "-q",
                "--overlay", SHAPES + ":fill=nope");
        assertEquals(2, tiles.exitCode(), tiles.err());
        assertTrue(tiles.err().contains("colour 'nope'"), tiles.err());
        assertFalse(Files.exists(out));
        assertFalse(Files.exists(dir.resolve("tiles")));
    }

    @Test
    void aProjectedPictureGetsTheShapes() throws IOException {
        Path plain = dir.resolve("plain.png");
        Path drawn = dir.resolve("drawn.png");
        assertEquals(0, render(plain, "--projection", "mollweide", "--width", "300").exitCode());
        CliRun r = render(drawn, "--projection", "mollweide", "--width", "300", "--overlay", SHAPES + ":width=3");
        assertEquals(0, r.exitCode(), r.err());
        java.awt.image.BufferedImage a = javax.imageio.ImageIO.read(plain.toFile());
        java.awt.image.BufferedImage b = javax.imageio.ImageIO.read(drawn.toFile());
        assertEquals(a.getWidth(), b.getWidth());
        int changed = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                changed += a.getRGB(x, y) != b.getRGB(x, y) ? 1 : 0;
            }
        }
        assertTrue(changed > 300, changed + " pixels changed");
    }

    @Test
    void grayProductsRefuseOverlaysNamingRender() {
        for (String command : new String[] {"hillshade", "shadows", "skyview"}) {
            Path out = dir.resolve(command + ".png");
            CliRun r = CliRun.of(command, DEM, "-o", out.toString(), "-q", "--overlay", SHAPES);
            assertEquals(2, r.exitCode(), command + ": " + r.err());
            assertTrue(r.err().contains("--overlay is not drawn on the one-band gray picture of " + command), r.err());
            assertTrue(r.err().contains("render --tint none --overlay"), r.err());
            assertFalse(Files.exists(out), command);
        }
    }
}
