package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.cli.Main;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.OutputOverwritesInputException;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.tint.ColorRamp;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link ReliefJob} makes the same files as the CLI, byte for byte, for every product: the library's one call is
 * the command line's whole work. Also README's "As a library" example: a window, the real sun, cast shadows.
 */
class ReliefJobTest {

    private static final Path TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    private static final Path LUX = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif");
    private static final Path VOLCANO = Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.flt");
    private static final Path VANCOUVER = Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.tif");
    private static final RenderSettings TWO_THREADS = new RenderSettings(2, RenderSettings.DEFAULT_TILE_SIZE);
    private static final WriteOptions NO_SIDECARS = WriteOptions.defaults()
            .withSidecars(WriteOptions.Sidecars.NONE);

    @TempDir
    Path tmp;

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

    private Path library(String name, ReliefJob job) throws IOException, InterruptedException {
        Path out = tmp.resolve("lib-" + name);
        job.withExecution(TWO_THREADS).runAndWrite(out, NO_SIDECARS, JobListener.NONE);
        return out;
    }

    private static void assertSameFile(Path expected, Path actual) throws IOException {
        assertArrayEquals(Files.readAllBytes(expected), Files.readAllBytes(actual), actual + " vs " + expected);
    }

    @Test
    void readmesWindowedRealSunShadowedRenderEqualsTheCli() throws IOException, InterruptedException {
        Path cli = cli("tujunga.png", "render", TUJUNGA.toString(), "--window", "380000,3790000,400000,3800000",
                "--sun-time", "2024-06-21T06:30-07:00[America/Los_Angeles]", "--shadows", "sweep", "--width", "400");
        // README, "As a library":
        ReliefResult relief = ReliefJob.of(TUJUNGA)
                .withWindow(Window.world(380000, 3790000, 400000, 3800000))
                .withSize(OutputSize.width(400))
                .withSun(Sun.at(ZonedDateTime.parse("2024-06-21T06:30-07:00[America/Los_Angeles]")))
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
                .withExecution(TWO_THREADS)
                .run(JobListener.NONE);
        Path lib = tmp.resolve("lib-tujunga.png");
        relief.write(lib, NO_SIDECARS);
        assertSameFile(cli, lib);
        assertEquals(400, relief.width());
        assertNotNull(relief.sun());
        assertEquals(67, relief.sun().azimuthDegrees(), 2);   // the README's caption: azimuth 67°, elevation 8°
    }

    @Test
    void hillshadeEqualsTheCli() throws IOException, InterruptedException {
        Path cli = cli("lux.tif", "hillshade", LUX.toString(), "--method", "horn", "--scale", "0.5",
                "--sun-azimuth", "315", "--sun-elevation", "45");
        Path lib = library("lux.tif", ReliefJob.of(LUX).withProduct(Product.HILLSHADE)
                .withScene(Scene.defaults().withHillshade(HillshadeMethod.HORN))
                .withSize(OutputSize.scale(0.5)).withSun(Sun.fixed(315, 45)));
        assertSameFile(cli, lib);
    }

    @Test
    void tintEqualsTheCli() throws IOException, InterruptedException {
        Path cli = cli("vancouver.png", "tint", VANCOUVER.toString(), "--tint", "etopo1");
        Path lib = library("vancouver.png", ReliefJob.of(VANCOUVER).withProduct(Product.TINT)
                .withScene(Scene.defaults().withTint(ColorRamp.named("etopo1"))));
        assertSameFile(cli, lib);
    }

    @Test
    void windowedShadowMaskEqualsTheCli() throws IOException, InterruptedException {
        Path cli = cli("volcano.png", "shadows", VOLCANO.toString(), "--algorithm", "sweep", "--sun-azimuth", "250",
                "--sun-elevation", "12", "--window", "cells:10,5,40,50");
        Path lib = library("volcano.png", ReliefJob.of(VOLCANO).withProduct(Product.SHADOWS)
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
                .withWindow(Window.cells(10, 5, 40, 50)).withSun(Sun.fixed(250, 12)));
        assertSameFile(cli, lib);
    }

    @Test
    void theBundledSampleWithDefaultsEqualsTheCli() throws IOException, InterruptedException {
        Path cli = cli("sample.png", "render");
        // the CLI's sample is a copy of this file (src/cli/resources/io/github/jdem846/sample/PROVENANCE.md)
        Path lib = library("sample.png", ReliefJob.of(
                Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif")));
        assertSameFile(cli, lib);
    }

    @Test
    void aProductDrawsOnlyItsOwnStagesAndReportsItsPhases() throws IOException, InterruptedException {
        List<String> phases = new ArrayList<>();
        List<String> stages = new ArrayList<>();
        JobListener listener = new JobListener() {
            @Override
            public void phaseDone(String phase) {
                phases.add(phase);
            }

            @Override
            public synchronized void update(String stage, long done, long total) {
                if (!stages.contains(stage)) {
                    stages.add(stage);
                }
            }
        };
        ReliefJob hillshade = ReliefJob.of(VOLCANO).withProduct(Product.HILLSHADE)
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.EXACT));   // shadows ignored
        ReliefResult r = hillshade.run(listener);
        assertEquals(List.of("read", "hillshade"), phases);
        assertEquals(List.of("read", "hillshade"), stages);
        assertNull(r.argb());
        assertNull(r.sun());
        assertEquals(r.width() * r.height(), r.gray().length);
    }

    @Test
    void aHillshadeGeoTiffMarksZeroAsNoDataAndAShadowMaskHasNone() throws IOException, InterruptedException {
        Path hs = library("hs.tif", ReliefJob.of(VOLCANO).withProduct(Product.HILLSHADE));
        assertEquals(0.0, io.github.jdem846.io.DemReader.inspect(hs).declaredNoData());
        Path mask = library("mask.tif", ReliefJob.of(VOLCANO).withProduct(Product.SHADOWS)
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP)));
        assertNull(io.github.jdem846.io.DemReader.inspect(mask).declaredNoData());
    }

    @Test
    void shadowMaskWithoutAnAlgorithmAndHillshadeWithoutAMethodAreRefused() {
        assertThrows(IllegalArgumentException.class,
                () -> ReliefJob.of(VOLCANO).withProduct(Product.SHADOWS).run(JobListener.NONE));
        assertThrows(IllegalArgumentException.class,
                () -> ReliefJob.of(VOLCANO).withScene(Scene.defaults().withHillshade(null))
                        .withProduct(Product.HILLSHADE).runAndWrite(tmp.resolve("x.png"), WriteOptions.defaults(),
                                JobListener.NONE));
        assertTrue(Files.notExists(tmp.resolve("x.png")));
        assertThrows(IllegalArgumentException.class, () -> Sun.fixed(300, 10).withTwilight(true));
    }

    @Test
    void anOutputOverTheInputIsRefusedBeforeReading() throws IOException {
        Path dem = Files.copy(TUJUNGA, tmp.resolve("dem.tif"));
        byte[] before = Files.readAllBytes(dem);
        assertThrows(OutputOverwritesInputException.class,
                () -> ReliefJob.of(dem).runAndWrite(dem, WriteOptions.defaults(), JobListener.NONE));
        assertArrayEquals(before, Files.readAllBytes(dem));
    }
}
