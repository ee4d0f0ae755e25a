package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.tint.ColorRamp;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A job measures a Web Mercator DEM's cells on the ground by default ({@link MercatorScale#GROUND}): slopes and cast
 * shadows come out as on the ground at every latitude, checked against sizes computed here by hand (x scale
 * cos φ/√(1 − e² sin² φ) on WGS 84, about cos φ); {@link MercatorScale#MAP} is the nominal measure of before.
 */
class WebMercatorScaleTest {

    private static final Path VANCOUVER = Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.tif");
    private static final RenderSettings TWO_THREADS = new RenderSettings(2, 64);
    private static final Scene HORN = Scene.defaults().withHillshade(HillshadeMethod.HORN);

    /** Ground metres per nominal Web Mercator metre east–west at {@code latitude}, on WGS 84, by hand. */
    private static double eastWestScale(double latitude) {
        double phi = Math.toRadians(latitude);
        double e2 = Ellipsoid.WGS84.eccentricitySquared();
        return Math.cos(phi) / Math.sqrt(1 - e2 * Math.sin(phi) * Math.sin(phi));
    }

    /** A Web Mercator grid of {@code w × h} cells of {@code cell} map metres whose middle row is at {@code lat}. */
    private static GridGeometry mercator(int w, int h, double cell, double latitude) {
        return new GridGeometry(w, h, 1.0e6, WebMercator.y(latitude) + h / 2.0 * cell, cell, cell, WebMercator.CRS,
                PixelAnchor.CORNER);
    }

    private static ReliefJob job(Product product, Scene scene, Sun sun) {
        return ReliefJob.of(VANCOUVER).withProduct(product).withScene(scene).withSun(sun)
                .withExecution(TWO_THREADS);
    }

    @Test
    void aPlaneRisingOneMetrePerGroundMetreEastwardShadesLike45DegreesAtEveryLatitude()
            throws InterruptedException {
        // the sun low in the west, 20° up, on a plane facing west: brighter the steeper up to 70°
        double sun = 20;
        int expected = HillshadeMethod.HORN.gray((float) westFacing(Math.toRadians(45), sun),
                HillshadeOptions.DEFAULTS);
        for (double latitude : new double[] {0, 30, 49, 60, 75}) {
            double cell = 1000;
            double ground = cell * eastWestScale(latitude);
            int w = 9;
            float[] z = new float[w * 3];
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < w; c++) {
                    z[r * w + c] = (float) (c * ground);
                }
            }
            Dem plane = Dem.ofNormalized(z, mercator(w, 3, cell, latitude), Double.NaN);
            ReliefJob hillshade = ReliefJob.of((DemInput) null).withProduct(Product.HILLSHADE)
                    .withScene(HORN).withSun(Sun.fixed(270, sun)).withExecution(TWO_THREADS);
            byte[] onGround = hillshade.run(plane, JobListener.NONE).gray();
            byte[] onMap = hillshade.withMercatorScale(MercatorScale.MAP).run(plane, JobListener.NONE).gray();
            // on the map a ground metre is 1/scale map metres: the slope is atan(scale), gentler away from the equator
            int gentler = HillshadeMethod.HORN.gray((float) westFacing(Math.atan(eastWestScale(latitude)), sun),
                    HillshadeOptions.DEFAULTS);
            for (int c = 0; c < w; c++) {
                assertEquals(expected, onGround[w + c] & 0xFF, "ground, latitude " + latitude + ", column " + c);
                assertEquals(gentler, onMap[w + c] & 0xFF, "map, latitude " + latitude + ", column " + c);
            }
            if (latitude >= 30) {
                assertTrue(expected - gentler >= 5, latitude + "°: " + expected + " vs " + gentler);
            }
        }
    }

    /**
     * cos i of a plane facing west with {@code slope} radians under the sun due west {@code elevation} degrees up:
     * sin e·cos s + cos e·sin s·cos(azimuth − aspect), azimuth = aspect.
     */
    private static double westFacing(double slope, double elevation) {
        double e = Math.toRadians(elevation);
        return Math.sin(e) * Math.cos(slope) + Math.cos(e) * Math.sin(slope);
    }

    @Test
    void eachRowOfVancouverShadesAsItsCellsScaledByCosLatitude() throws IOException, InterruptedException {
        Dem dem = DemReader.read(VANCOUVER);
        GridGeometry g = dem.geometry();
        assertTrue(WebMercator.isWebMercator(g.crs()), g.toString());
        LightDirection light = new LightDirection(315, 45);
        byte[] ground = job(Product.HILLSHADE, HORN, Sun.fixed(light)).run(JobListener.NONE).gray();
        byte[] map = job(Product.HILLSHADE, HORN, Sun.fixed(light)).withMercatorScale(MercatorScale.MAP)
                .run(JobListener.NONE).gray();
        int w = g.width();
        int differences = 0;
        for (int row : new int[] {1, 30, 60, 89}) {
            double latitude = WebMercator.latitude(g.centerY(row));
            Dem rows = dem.crop(0, row - 1, w, 3);
            byte[] scaled = horn(rows, HillshadeOptions.DEFAULTS.withHorizontalScale(Math.cos(Math.toRadians(
                    latitude))), light);
            byte[] nominal = horn(rows, HillshadeOptions.DEFAULTS.withHorizontalScale(1), light);
            for (int c = 0; c < w; c++) {
                int i = row * w + c;
                // within one level: the ellipsoid's sizes differ from the sphere's cos φ by under 0.7 %
                assertTrue(Math.abs((ground[i] & 0xFF) - (scaled[w + c] & 0xFF)) <= 1, "row " + row + " ("
                        + latitude + "°), column " + c + ": " + (ground[i] & 0xFF) + " vs " + (scaled[w + c] & 0xFF));
                assertEquals(nominal[w + c], map[i], "map metres, row " + row + ", column " + c);
                differences += Math.abs((ground[i] & 0xFF) - (map[i] & 0xFF)) > 3 ? 1 : 0;
            }
        }
        assertTrue(differences > 40, "ground and map metres differ at " + differences + " cells");
    }

    @Test
    void anEnlargedPictureIsMeasuredOnTheGroundToo() throws IOException, InterruptedException {
        // twice the size: the job resamples the whole grid to 240 × 182 cells, which keep their ground sizes
        Dem dem = DemReader.read(VANCOUVER);
        Dem enlarged = DemResampler.resample(dem, 2 * dem.width(), 2 * dem.height());
        ReliefJob hillshade = job(Product.HILLSHADE, HORN, Sun.fixed(315, 45)).withSize(OutputSize.scale(2));
        byte[] fromFile = hillshade.run(JobListener.NONE).gray();
        ReliefJob whole = hillshade.withSize(OutputSize.FULL);
        assertArrayEquals(whole.run(enlarged, JobListener.NONE).gray(), fromFile);
        assertFalse(java.util.Arrays.equals(whole.withMercatorScale(MercatorScale.MAP).run(enlarged,
                JobListener.NONE).gray(), fromFile), "map metres shade otherwise");
    }

    /** gdaldem's Horn hillshade of the middle row of a three-row DEM, 8-bit. */
    private static byte[] horn(Dem rows, HillshadeOptions options, LightDirection light) {
        float[] illumination = new float[rows.width() * rows.height()];
        HillshadeMethod.HORN.stage(options).illuminate(rows, light, 0, 0, rows.width(), rows.height(),
                illumination);
        return HillshadeMethod.HORN.toGray(illumination, options);
    }

    @Test
    void aWallCastsItsShadowOnTheGroundAtTwoLatitudes() throws InterruptedException {
        // a wall one cell wide along column 60, the sun due east 10° up: the shadow reaches L = h / tan 10° west,
        // L / (ground cell width) cells; in map metres it would be L / 100 cells at every latitude
        double cell = 100;
        double length = 1500;
        double height = length * Math.tan(Math.toRadians(10));
        int w = 70;
        int h = 5;
        int wall = 60;
        for (ShadowAlgorithm algorithm : new ShadowAlgorithm[] {ShadowAlgorithm.SWEEP, ShadowAlgorithm.EXACT}) {
            for (double latitude : new double[] {30, 60}) {
                float[] z = new float[w * h];
                for (int r = 0; r < h; r++) {
                    z[r * w + wall] = (float) height;
                }
                Dem dem = Dem.ofNormalized(z, mercator(w, h, cell, latitude), Double.NaN);
                ReliefJob mask = ReliefJob.of((DemInput) null).withProduct(Product.SHADOWS)
                        .withScene(Scene.defaults().withShadows(algorithm)).withSun(Sun.fixed(90, 10))
                        .withExecution(TWO_THREADS);
                double groundCells = length / (cell * eastWestScale(latitude));
                int onGround = shadowWest(mask.run(dem, JobListener.NONE).gray(), w, h / 2, wall);
                int onMap = shadowWest(mask.withMercatorScale(MercatorScale.MAP).run(dem, JobListener.NONE).gray(),
                        w, h / 2, wall);
                String what = algorithm + " at " + latitude + "°";
                assertEquals(groundCells, onGround, 1.0, what + ": " + onGround + " cells on the ground");
                assertEquals(length / cell, onMap, 1.0, what + ": " + onMap + " cells in map metres");
            }
        }
    }

    /** Cells in shadow west of {@code wall} in {@code row}, up to the first lit one. */
    private static int shadowWest(byte[] mask, int w, int row, int wall) {
        int n = 0;
        while (wall - n - 1 >= 0 && (mask[row * w + wall - n - 1] & 0xFF) > 127) {
            n++;
        }
        return n;
    }

    @Test
    void mapMetresAreTheNominalMeasureOfAProjectedGrid() throws IOException, InterruptedException {
        // the same cells in a projected CRS that is not Web Mercator are measured in nominal metres: the opt-out
        // draws exactly that, for every product
        Dem dem = DemReader.read(VANCOUVER);
        CrsInfo plain = CrsInfo.projected("a projected CRS in metres", null, 1.0, Ellipsoid.WGS84);
        Dem nominal = dem.withGeometry(dem.geometry().withCrs(plain));
        Scene scene = Scene.defaults().withTint(ColorRamp.named("etopo1")).withShadows(ShadowAlgorithm.SWEEP);
        for (Product product : Product.values()) {
            ReliefJob j = job(product, scene, Sun.fixed(300, 8));
            ReliefResult map = j.withMercatorScale(MercatorScale.MAP).run(JobListener.NONE);
            ReliefResult ground = j.run(JobListener.NONE);
            ReliefResult plainCells = j.run(nominal, JobListener.NONE);
            assertArrayEquals(plainCells.gray(), map.gray(), product.toString());
            assertArrayEquals(plainCells.argb(), map.argb(), product.toString());
            boolean sameOnGround = java.util.Arrays.equals(plainCells.gray(), ground.gray())
                    && java.util.Arrays.equals(plainCells.argb(), ground.argb());
            assertEquals(product == Product.TINT, sameOnGround, product + ": only the tint is not measured");
        }
    }

    @Test
    void theNoticeSaysWhatIsMeasuredOnTheGround() throws IOException, InterruptedException {
        List<String> notices = new ArrayList<>();
        JobListener listener = new JobListener() {
            @Override
            public void notice(String message) {
                notices.add(message);
            }
        };
        job(Product.RELIEF, Scene.defaults().withShadows(ShadowAlgorithm.SWEEP), Sun.fixed(300, 8)).run(listener);
        assertEquals(1, notices.size(), notices.toString());
        GridGeometry g = DemReader.inspect(VANCOUVER).geometry();
        double latitude = WebMercator.latitude(g.centerY(g.height() / 2));
        assertTrue(notices.get(0).startsWith(String.format(java.util.Locale.ROOT, "Web Mercator grid: slopes and "
                + "shadow lengths use the cells' ground size, row by row (%.1f m instead of %.1f map metres at the "
                + "centre, %.2f° N); --map-scale", g.cellWidth() * eastWestScale(latitude), g.cellWidth(),
                latitude)), notices.get(0));
        notices.clear();
        job(Product.SHADOWS, Scene.defaults().withShadows(ShadowAlgorithm.SWEEP), Sun.fixed(300, 8))
                .run(listener);
        assertTrue(notices.get(0).startsWith("Web Mercator grid: shadow lengths use"), notices.toString());
        notices.clear();
        job(Product.HILLSHADE, HORN.withHillshadeOptions(HillshadeOptions.DEFAULTS.withHorizontalScale(0.66)),
                Sun.fixed(300, 8)).run(listener);
        job(Product.TINT, Scene.defaults(), Sun.fixed(300, 8)).run(listener);
        job(Product.RELIEF, Scene.defaults(), Sun.fixed(300, 8)).withMercatorScale(MercatorScale.MAP).run(listener);
        assertFalse(notices.stream().anyMatch(n -> n.contains("Mercator")), notices.toString());
    }
}
