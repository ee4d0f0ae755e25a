package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.cli.Main;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.testing.TestDems;
import io.github.jdem846.tint.ColorRamp;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The default tint on a DEM with land and sea (Vancouver Island, −1437 to 2205 m): bathymetric below 0 m, table 2
 * above, the same in the library and the CLI; land-only DEMs keep the plain table 2.
 */
class TopoBathyDefaultTintTest {

    private static final Path VANCOUVER = Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.tif");
    private static final Path LUX = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif");
    private static final RenderSettings TWO_THREADS = new RenderSettings(2, RenderSettings.DEFAULT_TILE_SIZE);

    @TempDir
    Path tmp;

    @Test
    void seaIsBlueAndLandKeepsTable2OverZeroToMax() throws InterruptedException {
        Dem dem = TestDems.load(TestDems.VANCOUVER);
        ElevationStatistics all = dem.statistics();
        Renderer renderer = new Renderer(TWO_THREADS);
        int[] byDefault = renderer.render(dem, Scene.defaults()).argb();
        int[] table2OverLand = renderer.render(dem, Scene.defaults().withTint(ColorRamp.named("hypsometric"))
                .withTintRange(new ElevationStatistics(0, all.max(), all.validCount(), all.totalCount()))).argb();
        float[] cells = dem.backingArray();
        int sea = 0;
        for (int i = 0; i < cells.length; i++) {
            if (cells[i] < 0) {
                sea++;
                assertTrue(blue(byDefault[i]) > red(byDefault[i]),
                        "sea cell " + i + " at " + cells[i] + " m is " + Integer.toHexString(byDefault[i]));
            } else {
                assertEquals(table2OverLand[i], byDefault[i], "land cell " + i + " at " + cells[i] + " m");
            }
        }
        assertEquals(4841, sea);
    }

    @Test
    void explicitTable2StillStretchesOverTheWholeRange() throws InterruptedException {
        Dem dem = TestDems.load(TestDems.VANCOUVER);
        int[] plain = new Renderer(TWO_THREADS).render(dem, Scene.defaults().withTint(ColorRamp.named("hypsometric")))
                .argb();
        // 0 m lies at 39.5 % of [−1437, 2205]; from table 2's 5 % stop (E4CF7E) up to there every colour has more
        // red than blue, so all sea deeper than 5 % of the range is red-brown, as before the default split.
        ElevationStatistics all = dem.statistics();
        double fivePercent = all.min() + 0.05 * (all.max() - all.min());
        float[] cells = dem.backingArray();
        int reddish = 0;
        for (int i = 0; i < cells.length; i++) {
            if (cells[i] < 0 && cells[i] >= fivePercent) {
                reddish++;
                assertTrue(red(plain[i]) > blue(plain[i]), "sea cell " + i + " at " + cells[i] + " m");
            }
        }
        assertTrue(reddish > 4800, "nearly all of the 4841 sea cells lie above 5 %: " + reddish);
    }

    @Test
    void seaLevelTakesTheLandRampsFirstColour() throws IOException, InterruptedException {
        ReliefResult tint = ReliefJob.of(VANCOUVER).withProduct(Product.TINT).withExecution(TWO_THREADS)
                .run(JobListener.NONE);
        float[] cells = TestDems.load(TestDems.VANCOUVER).backingArray();
        int atZero = 0;
        for (int i = 0; i < cells.length; i++) {
            if (cells[i] == 0) {
                atZero++;
                assertEquals(0xFF006246, tint.argb()[i], "cell " + i + " at 0 m");
            }
        }
        assertEquals(9, atZero);
    }

    @Test
    void theLibraryAndTheCliAgree() throws IOException, InterruptedException {
        Path cli = cli("vancouver.png", "render", VANCOUVER.toString());
        Path lib = tmp.resolve("lib-vancouver.png");
        ReliefJob.of(VANCOUVER).withExecution(TWO_THREADS).run(JobListener.NONE)
                .write(lib, WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE));
        assertArrayEquals(Files.readAllBytes(cli), Files.readAllBytes(lib));
        BufferedImage image = ImageIO.read(cli.toFile());
        float[] cells = TestDems.load(TestDems.VANCOUVER).backingArray();
        for (int i = 0; i < cells.length; i++) {
            int c = image.getRGB(i % image.getWidth(), i / image.getWidth());
            assertTrue(cells[i] >= 0 || blue(c) > red(c), "sea cell " + i + " at " + cells[i] + " m");
        }
    }

    @Test
    void aLandOnlyDemRendersAsWithExplicitTable2() throws IOException {
        Path byDefault = cli("lux-default.png", "render", LUX.toString());
        Path table2 = cli("lux-table2.png", "render", LUX.toString(), "--tint", "hypsometric");
        assertArrayEquals(Files.readAllBytes(table2), Files.readAllBytes(byDefault));
    }

    private Path cli(String name, String... args) {
        Path out = tmp.resolve("cli-" + name);
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(List.of("-o", out.toString(), "-q", "--threads", "2"));
        String[] argv = all.toArray(String[]::new);
        StringWriter err = new StringWriter();
        var cl = Main.commandLine(argv);
        cl.setErr(new PrintWriter(err, true));
        cl.setOut(new PrintWriter(new StringWriter(), true));
        assertEquals(0, cl.execute(argv), err.toString());
        return out;
    }

    private static int red(int argb) {
        return argb >> 16 & 0xFF;
    }

    private static int blue(int argb) {
        return argb & 0xFF;
    }
}
