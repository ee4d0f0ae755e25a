package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code render --blend} and {@code --hillshade-opacity} end to end: against ImageMagick's composite of the
 * {@code tint} and {@code hillshade} pictures (testdata/golden/blend, README there), and the properties every mode
 * must have on real DEMs.
 */
class BlendCliTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";
    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final String WINDOW = "cells:560,200,160,100";
    private static final Path GOLDEN = Path.of("testdata/golden/blend");
    private static final String[] CASE_B_TINT = {"--tint", "etopo1"};
    private static final String[] CASE_B_SHADE = {"--sun-azimuth", "200", "--sun-elevation", "40", "-z", "2",
        "--light-intensity", "1", "--dark-intensity", "0.8"};

    @TempDir
    Path dir;

    private Path run(String command, String name, String... args) {
        Path out = dir.resolve(name + ".png");
        List<String> all = new ArrayList<>(List.of(command));
        all.addAll(List.of(args));
        all.addAll(List.of("-o", out.toString(), "-q"));
        CliRun r = CliRun.of(all.toArray(String[]::new));
        assertEquals(0, r.exitCode(), r.err());
        return out;
    }

    private static int[] argb(Path png) throws IOException {
        BufferedImage img = ImageIO.read(png.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }

    private static String[] concat(String[]... parts) {
        List<String> all = new ArrayList<>();
        for (String[] p : parts) {
            all.addAll(List.of(p));
        }
        return all.toArray(String[]::new);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"bt_a_multiply, multiply, a", "bt_a_screen, screen, a", "bt_a_overlay, overlay, a",
        "bt_a_soft-light, soft-light, a", "bt_b_multiply, multiply, b", "bt_b_soft-light, soft-light, b"})
    void matchesImageMagicksCompositeOfTheTintAndHillshadeWithinOneLevel(String golden, String mode, String kase)
            throws IOException {
        String[] options = kase.equals("a") ? new String[0] : concat(CASE_B_TINT, CASE_B_SHADE);
        int[] ours = argb(run("render", golden, concat(new String[] {BT, "--window", WINDOW, "--blend", mode},
                options)));
        int[] reference = argb(GOLDEN.resolve(golden + ".png"));
        assertEquals(reference.length, ours.length);
        int worst = 0;
        for (int i = 0; i < ours.length; i++) {
            assertEquals(0xFF, ours[i] >>> 24, "opaque at " + i);
            for (int shift = 0; shift <= 16; shift += 8) {
                worst = Math.max(worst, Math.abs(((ours[i] >> shift) & 0xFF) - ((reference[i] >> shift) & 0xFF)));
            }
        }
        assertTrue(worst <= 1, golden + ": largest difference " + worst + " levels");
    }

    @Test
    void theDefaultIsEqEightFullyOpaqueByteForByte() throws IOException {
        Path golden = Path.of("testdata/golden/render/vo_jdem846_sweep_az100_alt12.png");
        Path ours = run("render", "vo", "testdata/dem/maungawhau-volcano_10m_nztm-approx.tif", "--shadows", "sweep",
                "--sun-elevation", "12", "--sun-azimuth", "100", "--blend", "jdem846", "--hillshade-opacity", "1");
        assertArrayEquals(argb(golden), argb(ours));
    }

    /**
     * On Luxembourg (3942 no-data cells) with cast shadows: no-data stays transparent in every mode, the original's
     * LIGHTEN is never darker than the tint and DARKEN never lighter, and opacity 0 is the tint itself.
     */
    @Test
    void propertiesOnARealDemWithNoData() throws IOException {
        int[] tint = argb(run("tint", "tint", LUX));
        String[] common = {LUX, "--shadows", "sweep", "--sun-elevation", "15"};
        int transparent = 0;
        for (int i = 0; i < tint.length; i++) {
            transparent += tint[i] >>> 24 == 0 ? 1 : 0;
        }
        assertTrue(transparent > 3000, transparent + " no-data pixels");
        for (String mode : new String[] {"jdem846", "jdem846-lighten", "jdem846-darken", "multiply", "screen",
            "overlay", "soft-light"}) {
            int[] px = argb(run("render", mode, concat(common, new String[] {"--blend", mode})));
            for (int i = 0; i < px.length; i++) {
                assertEquals(tint[i] >>> 24 == 0, px[i] == 0, mode + ": no-data transparent at " + i);
            }
            assertArrayEquals(tint, argb(run("render", mode + "-0", concat(common, new String[] {"--blend", mode,
                "--hillshade-opacity", "0"}))), mode + " at opacity 0 is the tint");
        }
        int[] lighter = argb(run("render", "lighten", concat(common, new String[] {"--blend", "jdem846-lighten"})));
        int[] darker = argb(run("render", "darken", concat(common, new String[] {"--blend", "jdem846-darken"})));
        int changedLight = 0;
        int changedDark = 0;
        for (int i = 0; i < tint.length; i++) {
            for (int shift = 0; shift <= 16; shift += 8) {
                int c = (tint[i] >> shift) & 0xFF;
                assertTrue(((lighter[i] >> shift) & 0xFF) >= c, "lighten at " + i);
                assertTrue(((darker[i] >> shift) & 0xFF) <= c, "darken at " + i);
            }
            changedLight += lighter[i] != tint[i] ? 1 : 0;
            changedDark += darker[i] != tint[i] ? 1 : 0;
        }
        int valid = tint.length - transparent;
        assertTrue(changedLight > valid / 2 && changedDark > valid / 2, changedLight + ", " + changedDark);
    }

    @Test
    void theOriginalsLightingMultipleMixesTintAndRelief() throws IOException {
        int[] tint = argb(run("tint", "tint", BT, "--window", WINDOW));
        int[] full = argb(run("render", "full", BT, "--window", WINDOW));
        int[] mixed = argb(run("render", "mixed", BT, "--window", WINDOW, "--hillshade-opacity", "0.75"));
        for (int i = 0; i < tint.length; i++) {
            for (int shift = 0; shift <= 16; shift += 8) {
                double expected = 0.25 * ((tint[i] >> shift) & 0xFF) + 0.75 * ((full[i] >> shift) & 0xFF);
                assertEquals(expected, (mixed[i] >> shift) & 0xFF, 1.0, "pixel " + i);
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "--blend lighten | --blend | unknown blend mode 'lighten' | soft-light",
        "--blend multiply --hillshade-opacity 1.5 | --hillshade-opacity | between 0 and 1 | got 1.5",
        "--hillshade-opacity NaN | --hillshade-opacity | between 0 and 1 | got NaN"})
    void badValuesAreOneLineNamingTheOption(String args, String option, String says, String alsoSays) {
        Path out = dir.resolve("bad.png");
        List<String> all = new ArrayList<>(List.of("render", BT, "-o", out.toString(), "-q"));
        all.addAll(List.of(args.trim().split(" ")));
        CliRun r = CliRun.of(all.toArray(String[]::new));
        assertEquals(2, r.exitCode(), r.err());
        String first = r.err().lines().findFirst().orElse("");
        assertTrue(first.startsWith("jdem846: ") && first.contains(option) && first.contains(says)
                && (alsoSays == null || first.contains(alsoSays)), r.err());
        assertFalse(r.err().contains("Exception"), r.err());
        assertFalse(Files.exists(out));
    }
}
