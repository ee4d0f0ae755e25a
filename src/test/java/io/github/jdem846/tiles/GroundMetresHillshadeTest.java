package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.CellWindow;
import org.junit.jupiter.api.Test;

/**
 * Slopes in map tiles are measured in ground metres: the Horn illumination of the Jacksboro DEM (36.6° N) computed on
 * a zoom-11 Web Mercator grid sampled from it agrees with the illumination computed on the DEM's own latitude/longitude
 * grid (interpolated to the same places), and clearly better than on the same grid with Web Mercator's nominal metres,
 * which are 1/cos 36.6° = 1.25 times too long here and flatten every slope.
 */
class GroundMetresHillshadeTest {

    @Test
    void mercatorHillshadeMatchesTheDemsOwnGrid() throws Exception {
        DemInput input = DemInput.of(TileJobTest.DEM);
        DemInfo info = DemReader.inspect(input).withDefaultEllipsoid(Ellipsoid.WGS84);
        Dem own = DemReader.read(TileJobTest.DEM);
        HillshadeOptions options = HillshadeOptions.DEFAULTS;
        LightField light = LightField.uniform(new LightDirection(315, 45));
        Renderer renderer = new Renderer(new RenderSettings(1, 256));
        float[] reference = renderer.illumination(own, HillshadeMethod.HORN.stage(options), light,
                RenderProgress.NONE);

        int z = 11;
        ZoomGrid grid = new ZoomGrid(z);
        SourceProjection projection = SourceProjection.of(info.geometry(), info.source());
        ZoomSource source = new ZoomSource(input, projection, grid);
        double lonC = (TileJobTest.WEST + TileJobTest.EAST) / 2;
        double latC = (TileJobTest.NORTH + TileJobTest.SOUTH) / 2;
        int n = 300;
        int col0 = (int) TileJobTest.column(lonC, z) - n / 2;
        int row0 = (int) TileJobTest.row(latC, z) - n / 2;
        CellWindow block = new CellWindow(col0, row0, n, n);
        float[] values = source.read(block).sample(grid, col0, row0, n, n);
        GridGeometry ground = grid.window(col0, row0, n, n);
        GridGeometry nominal = new GridGeometry(n, n, ground.originX(), ground.originY(), ground.cellWidth(),
                ground.cellHeight(), WebMercator.CRS, PixelAnchor.CORNER);
        float[] onGround = renderer.illumination(Dem.ofNormalized(values, ground, Double.NaN),
                HillshadeMethod.HORN.stage(options), light, RenderProgress.NONE);
        float[] onNominal = renderer.illumination(Dem.ofNormalized(values.clone(), nominal, Double.NaN),
                HillshadeMethod.HORN.stage(options), light, RenderProgress.NONE);

        double cellDeg = info.geometry().cellWidth();
        double sumGround = 0;
        double sumNominal = 0;
        Spread refSpread = new Spread();
        Spread groundSpread = new Spread();
        Spread nominalSpread = new Spread();
        int count = 0;
        for (int r = 2; r < n - 2; r++) {
            double lat = WebMercator.latitude(grid.centerY(row0 + r));
            for (int c = 2; c < n - 2; c++) {
                double lon = WebMercator.longitude(grid.centerX(col0 + c));
                double u = (lon - info.geometry().originX()) / cellDeg - 0.5;
                double v = (info.geometry().originY() - lat) / info.geometry().cellHeight() - 0.5;
                double ref = bilinear(reference, own.width(), u, v);
                double g = onGround[r * n + c];
                double m = onNominal[r * n + c];
                sumGround += Math.abs(g - ref);
                sumNominal += Math.abs(m - ref);
                refSpread.add(ref);
                groundSpread.add(g);
                nominalSpread.add(m);
                count++;
            }
        }
        double madGround = sumGround / count;
        double madNominal = sumNominal / count;
        System.out.printf(java.util.Locale.ROOT, "cos-incidence mean |tile − own grid| over %d pixels: ground "
                + "metres %.4f, nominal metres %.4f; standard deviation: own grid %.4f, ground %.4f, nominal %.4f%n",
                count, madGround, madNominal, refSpread.sd(), groundSpread.sd(), nominalSpread.sd());
        assertTrue(madGround < 0.03, "ground metres: mean difference " + madGround);
        assertTrue(madGround < 0.6 * madNominal, "ground " + madGround + " vs nominal " + madNominal);
        // nominal metres flatten the relief: the illumination varies less than on the DEM's own grid; ground
        // metres keep its spread within 5 %
        assertTrue(nominalSpread.sd() < 0.9 * refSpread.sd(), "nominal metres flatten");
        assertTrue(Math.abs(groundSpread.sd() / refSpread.sd() - 1) < 0.05, "ground metres keep the contrast");
    }

    /** Mean and standard deviation of a series. */
    private static final class Spread {
        private double sum;
        private double squares;
        private long n;

        void add(double x) {
            sum += x;
            squares += x * x;
            n++;
        }

        double sd() {
            double mean = sum / n;
            return Math.sqrt(squares / n - mean * mean);
        }
    }

    private static double bilinear(float[] a, int width, double u, double v) {
        int c = (int) Math.floor(u);
        int r = (int) Math.floor(v);
        double fu = u - c;
        double fv = v - r;
        return (1 - fv) * ((1 - fu) * a[r * width + c] + fu * a[r * width + c + 1])
                + fv * ((1 - fu) * a[(r + 1) * width + c] + fu * a[(r + 1) * width + c + 1]);
    }
}
