package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.DemTiles;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every product of a mosaic of tiles cut from a real DEM is the product of the DEM itself, byte for byte: the
 * relief, hillshade, tint and cast shadows, whole and through a reduced window whose shadow halo reaches into
 * the neighbouring tiles. A low sun from the north-west casts shadows across both seams: a tile rendered alone
 * lacks the shadows its neighbours cast into it, the same tile rendered as a window of the mosaic has them.
 */
class MosaicRenderTest {

    private static final Path DEM = Path.of("testdata", "dem");
    private static final RenderSettings TWO_THREADS = new RenderSettings(2, 128);
    private static final WriteOptions NO_SIDECARS = WriteOptions.defaults()
            .withSidecars(WriteOptions.Sidecars.NONE);
    /** Low in the north-west: the long shadows of the ridges fall south-east, over the seams. */
    private static final Sun LOW_SUN = Sun.fixed(315, 8);

    @TempDir
    static Path tmp;

    /** 600 × 400 cells of Big Tujunga's ridges, written as one GridFloat. */
    private static Path TUJUNGA;
    private static List<Path> tiles;

    @BeforeAll
    static void cut() throws IOException {
        Dem source = DemReader.read(DEM.resolve("bigtujunga_srtm30m_utm11n.flt"));
        Path prj = DEM.resolve("bigtujunga_srtm30m_utm11n.prj");
        TUJUNGA = tmp.resolve("whole.flt");
        DemTiles.writeGridFloat(TUJUNGA, DemTiles.cells(source, new DemTiles.Cut(300, 100, 600, 400)),
                source.geometry(), new DemTiles.Cut(300, 100, 600, 400), prj);
        tiles = DemTiles.gridFloat(DemReader.read(TUJUNGA), DemTiles.quarters(600, 400, 301, 201, 1), tmp, "t",
                prj);
    }

    private static byte[] png(String name, ReliefJob job) throws IOException, InterruptedException {
        Path out = tmp.resolve(name + ".png");
        job.withExecution(TWO_THREADS).runAndWrite(out, NO_SIDECARS, JobListener.NONE);
        return Files.readAllBytes(out);
    }

    private static void assertSameProduct(String name, ReliefJob job) throws IOException, InterruptedException {
        byte[] whole = png(name + "-whole", job);
        byte[] mosaic = png(name + "-mosaic", withInput(job, DemInput.of(tiles)));
        assertArrayEquals(whole, mosaic, name + ": the mosaic's picture differs from the whole DEM's");
    }

    @Test
    void everyProductOfTheMosaicIsTheWholeDemsByteForByte() throws IOException, InterruptedException {
        Scene shadows = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
        ReliefJob base = ReliefJob.of(DemInput.of(TUJUNGA)).withSun(LOW_SUN).withScene(shadows);
        assertSameProduct("relief", base.withProduct(Product.RELIEF));
        assertSameProduct("hillshade", base.withProduct(Product.HILLSHADE));
        assertSameProduct("tint", base.withProduct(Product.TINT));
        assertSameProduct("shadows", base.withProduct(Product.SHADOWS));
        // a window across both seams at a third of the size: decimated read, and a shadow halo into the tiles
        assertSameProduct("window", base.withProduct(Product.RELIEF)
                .withWindow(Window.cells(200, 120, 250, 200)).withSize(OutputSize.width(83)));
    }

    @Test
    void shadowsCrossTheSeams() throws IOException, InterruptedException {
        // the south-east tile: alone, and as a window of the mosaic (where its neighbours' ridges shade it)
        Scene shadows = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
        ReliefJob job = ReliefJob.of(DemInput.of(tiles.get(3))).withProduct(Product.SHADOWS).withSun(LOW_SUN)
                .withScene(shadows);
        byte[] alone = png("se-alone", job);
        Window se = Window.cells(301, 201, 299, 199);
        byte[] inMosaic = png("se-in-mosaic", withInput(job.withWindow(se), DemInput.of(tiles)));
        byte[] inWhole = png("se-in-whole", withInput(job.withWindow(se), DemInput.of(TUJUNGA)));
        assertArrayEquals(inWhole, inMosaic, "the tile as a window of the mosaic and of the whole DEM");
        assertFalse(Arrays.equals(alone, inMosaic), "no shadow crossed into the tile");
        assertTrue(shadowedCells(inMosaic) > shadowedCells(alone), "the neighbours add shadows");
    }

    @Test
    void aGeographicMosaicRendersAsItsWholeDem() throws IOException, InterruptedException {
        Path jacksboro = DEM.resolve("jacksboro_srtm3s_wgs84.tif");
        Dem whole = DemReader.read(jacksboro);
        List<Path> j = DemTiles.geoTiff(whole, DemTiles.quarters(403, 344, 200, 170, 1),
                Files.createDirectories(tmp.resolve("jacksboro")), "j", 4326, true);
        ReliefJob job = ReliefJob.of(DemInput.of(jacksboro)).withSun(Sun.fixed(135, 6))
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP)).withExecution(TWO_THREADS);
        byte[] a = png("jacksboro-whole", job);
        byte[] b = png("jacksboro-mosaic", withInput(job, DemInput.of(j)));
        assertArrayEquals(a, b, "geographic mosaic");
    }

    /** The same job on another input. */
    private static ReliefJob withInput(ReliefJob job, DemInput input) {
        return new ReliefJob(input, job.product(), job.scene(), job.window(), job.size(), job.sun(), job.body(),
                job.execution());
    }

    /** Pixels of a shadow mask PNG in shadow (0 is lit). */
    private static long shadowedCells(byte[] png) throws IOException {
        var img = javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(png));
        long n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if (img.getRaster().getSample(x, y, 0) > 0) {
                    n++;
                }
            }
        }
        return n;
    }
}
