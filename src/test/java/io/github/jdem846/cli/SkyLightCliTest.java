package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.SkyView;
import io.github.jdem846.shadow.SkyViewOptions;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ForkJoinPool;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code render --light-model/--ambient} and {@code skyview}, end to end on real DEMs. */
class SkyLightCliTest {

    private static final String VOLCANO = "testdata/dem/maungawhau-volcano_10m_nztm-approx.tif";
    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final Path GOLDEN = Path.of("testdata/golden/render/vo_jdem846_sweep_az100_alt12.png");

    @TempDir
    Path dir;

    private Path render(String name, String... extra) {
        Path out = dir.resolve(name + ".png");
        String[] base = {"render", VOLCANO, "-o", out.toString(), "--shadows", "sweep", "--sun-elevation", "12",
            "--sun-azimuth", "100"};
        String[] args = new String[base.length + extra.length];
        System.arraycopy(base, 0, args, 0, base.length);
        System.arraycopy(extra, 0, args, base.length, extra.length);
        CliRun run = CliRun.of(args);
        assertEquals(0, run.exitCode(), run.err());
        return out;
    }

    private static int[] argb(Path png) throws IOException {
        BufferedImage img = ImageIO.read(png.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }

    @Test
    void theOriginalLightModelRendersAsBefore() throws IOException {
        int[] golden = argb(GOLDEN);
        assertTrue(java.util.Arrays.equals(golden, argb(render("default"))));
        assertTrue(java.util.Arrays.equals(golden, argb(render("jdem846", "--light-model", "jdem846"))));
        assertTrue(java.util.Arrays.equals(golden, argb(render("jdem846-0", "--light-model", "jdem846",
                "--ambient", "0"))));
    }

    @Test
    void ambientZeroIsTheRenderWithoutSkyLightAndTheSkyModelHasIt() throws IOException {
        int[] none = argb(render("sky-0", "--light-model", "sky", "--ambient", "0"));
        int[] dflt = argb(render("sky", "--light-model", "sky"));
        int[] half = argb(render("sky-half", "--light-model", "sky", "--ambient", "0.5"));
        assertFalse(java.util.Arrays.equals(none, dflt));
        // more sky light never darkens a pixel: compare the green channel of every opaque pixel
        int brighter = 0;
        for (int i = 0; i < none.length; i++) {
            int g0 = (none[i] >> 8) & 0xFF;
            int g1 = (dflt[i] >> 8) & 0xFF;
            int g2 = (half[i] >> 8) & 0xFF;
            assertTrue(g0 <= g1 && g1 <= g2, "pixel " + i + ": " + g0 + ", " + g1 + ", " + g2);
            brighter += g1 > g0 ? 1 : 0;
        }
        assertTrue(brighter > none.length / 2, brighter + " of " + none.length);
    }

    @Test
    void skyviewWritesTheFactorAsGray() throws IOException {
        Path out = dir.resolve("svf.png");
        CliRun run = CliRun.of("skyview", LUX, "-o", out.toString(), "--directions", "16");
        assertEquals(0, run.exitCode(), run.err());
        Dem dem = DemReader.read(Path.of(LUX));
        float[] f = SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(16), ForkJoinPool.commonPool());
        Raster r = ImageIO.read(out.toFile()).getRaster();
        int noData = 0;
        for (int y = 0; y < dem.height(); y++) {
            for (int x = 0; x < dem.width(); x++) {
                float v = f[y * dem.width() + x];
                int expected = Float.isNaN(v) ? 0 : 1 + Math.round(v * 254);
                assertEquals(expected, r.getSample(x, y, 0), "cell " + x + ", " + y);
                noData += Float.isNaN(v) ? 1 : 0;
            }
        }
        assertEquals(3942, noData);
        assertFalse(Files.exists(dir.resolve("svf.png.tmp")));
    }

    @Test
    void skyviewWritesTheFactorAsFloat32WithinASearchRadius() throws IOException {
        Path out = dir.resolve("svf.tif");
        CliRun run = CliRun.of("skyview", LUX, "-o", out.toString(), "--directions", "16", "--float",
                "--sky-radius", "9000");
        assertEquals(0, run.exitCode(), run.err());
        Dem dem = DemReader.read(Path.of(LUX));
        float[] f = SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(16).withRadius(9000),
                ForkJoinPool.commonPool());
        float[] unbounded = SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(16),
                ForkJoinPool.commonPool());
        Dem written = DemReader.read(out);
        assertEquals(dem.geometry().originX(), written.geometry().originX(), 0);
        assertEquals(dem.geometry().originY(), written.geometry().originY(), 0);
        assertEquals(dem.geometry().cellWidth(), written.geometry().cellWidth(), 0);
        assertEquals(dem.geometry().crs().epsg(), written.geometry().crs().epsg());
        float[] v = written.backingArray();
        int differs = 0;
        for (int i = 0; i < f.length; i++) {
            assertEquals(Float.isNaN(f[i]), Float.isNaN(v[i]), "no-data at " + i);
            if (!Float.isNaN(f[i])) {
                assertEquals(f[i], v[i], 0f, "cell " + i);
                assertTrue(v[i] >= unbounded[i], "a radius never hides sky, cell " + i);
                differs += v[i] > unbounded[i] ? 1 : 0;
            }
        }
        assertTrue(differs > 0, "9 km (about 15 cells) is shorter than some horizons");
    }

    @Test
    void badSkyOptionsAreRefusedInOneLine() {
        String[][] bad = {{"render", VOLCANO, "--ambient", "1.5"}, {"render", VOLCANO, "--sky-directions", "3"},
            {"render", VOLCANO, "--light-model", "moon"}, {"skyview", VOLCANO, "--directions", "400"},
            {"render", VOLCANO, "--sky-radius", "0"}, {"skyview", VOLCANO, "--sky-radius", "-5"},
            {"skyview", VOLCANO, "--sky-radius", "Infinity"}, {"skyview", VOLCANO, "--sky-radius", "far"},
            {"skyview", VOLCANO, "--float", "--directions", "8"}};
        for (String[] args : bad) {
            String[] withOut = java.util.Arrays.copyOf(args, args.length + 2);
            withOut[args.length] = "-o";
            withOut[args.length + 1] = dir.resolve("x.png").toString();
            CliRun run = CliRun.of(withOut);
            assertEquals(2, run.exitCode(), String.join(" ", args) + ": " + run.err());
            String first = run.err().lines().findFirst().orElse("");
            assertTrue(first.contains(args[2].substring(2)), first);   // the option, by any of its names
            assertFalse(run.err().contains("Exception"), run.err());
            assertFalse(Files.exists(dir.resolve("x.png")));
        }
    }

    @Test
    void floatValuesAreNotProjected() {
        Path out = dir.resolve("svf.tif");
        CliRun run = CliRun.of("skyview", VOLCANO, "--float", "--directions", "8", "--projection", "mollweide",
                "-o", out.toString());
        assertEquals(2, run.exitCode(), run.err());
        String first = run.err().lines().findFirst().orElse("");
        assertTrue(first.contains("--projection") && first.contains("--float"), first);
        assertFalse(Files.exists(out));
    }
}
