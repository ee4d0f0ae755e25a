package io.github.jdem846.overlay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.projection.MapProjection;
import io.github.jdem846.projection.ProjectedExtent;
import io.github.jdem846.projection.ProjectedPicture;
import io.github.jdem846.projection.ProjectionName;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.opengis.referencing.operation.MathTransform;

/**
 * Overlays on pictures in a map projection ({@link ProjectedOverlays}): points land on the pixel Apache SIS's
 * forward transform of their longitude and latitude predicts (computed here, from the projection's CRS and the
 * picture's extent); the Big Tujunga test line and triangle on a World Mercator (EPSG:3395) picture land where
 * {@code gdal_rasterize} puts them after {@code ogr2ogr -t_srs EPSG:3395}; lines and polygons crossing the meridian
 * opposite the central one are cut at the map's edges instead of drawn across the picture.
 */
class ProjectedOverlaysTest {

    static final GeometryFactory GF = new GeometryFactory();
    /** Lines 2 px wide (so that each covers a whole pixel row wherever it lies), discs of radius 2 px. */
    static final OverlayStyle WHITE = new OverlayStyle(Color.WHITE, 2, Color.WHITE, 2);

    static ProjectedPicture world(MapProjection map, int width) {
        GridGeometry world = new GridGeometry(360, 180, -180, 90, 1, 1, CrsInfo.WGS84, PixelAnchor.CORNER);
        ProjectedExtent extent = ProjectedExtent.of(world, map);
        int[] size = extent.pixels(width, 0);
        return new ProjectedPicture(map, extent, size[0], size[1], new int[size[0] * size[1]]);
    }

    static Overlay lonLat(Geometry... geometries) {
        return new Overlay("test", List.of(geometries), OverlayFiles.crs84(), WHITE);
    }

    static int[] draw(ProjectedPicture picture, Overlay overlay) {
        return ProjectedOverlays.paint(picture, List.of(overlay)).argb();
    }

    @Test
    void aPointLandsOnThePixelSisPredicts() throws Exception {
        for (MapProjection map : List.of(MapProjection.named(ProjectionName.MOLLWEIDE, 0),
                MapProjection.named(ProjectionName.ROBINSON, 30), MapProjection.fromEpsg(3395))) {
            ProjectedPicture picture = world(map, 720);
            MathTransform forward = CRS.findOperation(CommonCRS.WGS84.normalizedGeographic(), map.crs(), null)
                    .getMathTransform();
            double pw = picture.extent().width() / picture.width();
            double ph = picture.extent().height() / picture.height();
            for (double[] lonLat : new double[][] {{0, 0}, {-120.3, 45.2}, {150.7, -60.1}, {10, 80}, {-179, -30}}) {
                double[] xy = new double[2];
                // SIS does not wrap longitudes: give it the one within half a turn of the central meridian
                double lon = lonLat[0] + 360 * Math.rint((map.centralMeridian() - lonLat[0]) / 360);
                forward.transform(new double[] {lon, lonLat[1]}, 0, xy, 0, 1);
                double col = (xy[0] - picture.extent().west()) / pw;
                double row = (picture.extent().north() - xy[1]) / ph;
                if (row < 3 || row > picture.height() - 3) {
                    continue; // beyond Mercator's ±85°: off the picture
                }
                int[] argb = draw(picture, lonLat(GF.createPoint(new Coordinate(lonLat[0], lonLat[1]))));
                double sum = 0;
                double sx = 0;
                double sy = 0;
                for (int i = 0; i < argb.length; i++) {
                    int a = argb[i] >>> 24;
                    sum += a;
                    sx += a * (i % picture.width() + 0.5);
                    sy += a * (i / picture.width() + 0.5);
                }
                String what = map + " at " + lonLat[0] + ", " + lonLat[1];
                assertEquals(Math.PI * 4 * 255, sum, 0.15 * Math.PI * 4 * 255, what + ": a disc of radius 2 px");
                assertEquals(col, sx / sum, 0.25, what);
                assertEquals(row, sy / sum, 0.25, what);
            }
        }
    }

    @Test
    void lonLatShapesLandOnTheWorldMercatorPictureWhereGdalRasterizePutsThem() throws IOException {
        // the frame gdal_rasterize was given (testdata/overlay/README.md)
        ProjectedPicture picture = new ProjectedPicture(MapProjection.fromEpsg(3395),
                new ProjectedExtent(-13174186.76, 4035878.30, -13130480.58, 4059705.64), 600, 327,
                new int[600 * 327]);
        int w = picture.width();
        int h = picture.height();
        Overlay shapes = OverlayFiles.read(OverlayPainterTest.DIR.resolve("bigtujunga_test_shapes.geojson"),
                new OverlayStyle(Color.WHITE, 1, Color.WHITE, 0));
        boolean[] lineGolden = golden("line", w, h);
        int[] line = draw(picture, OverlayPainterTest.only(shapes, org.locationtech.jts.geom.LineString.class));
        int goldenCount = 0;
        for (int i = 0; i < lineGolden.length; i++) {
            if (lineGolden[i]) {
                goldenCount++;
                assertTrue(OverlayPainterTest.near(line, w, h, i % w, i / w, 1, 1), "gdal's line pixel " + i % w
                        + "," + i / w);
            }
            if ((line[i] >>> 24) >= 128) {
                assertTrue(OverlayPainterTest.near(lineGolden, w, h, i % w, i / w), "our line pixel " + i % w + ","
                        + i / w);
            }
        }
        assertTrue(goldenCount > 400, "the golden line has " + goldenCount + " pixels");

        boolean[] polygonGolden = golden("polygon", w, h);
        int[] polygon = draw(picture, OverlayPainterTest.only(shapes, org.locationtech.jts.geom.Polygon.class)
                .withStyle(new OverlayStyle(Color.WHITE, 0, Color.WHITE, 0)));
        int expected = 0;
        int ours = 0;
        int differ = 0;
        for (int i = 0; i < polygon.length; i++) {
            boolean in = (polygon[i] >>> 24) >= 128;
            expected += polygonGolden[i] ? 1 : 0;
            ours += in ? 1 : 0;
            differ += in != polygonGolden[i] ? 1 : 0;
            if (in != polygonGolden[i]) {
                assertTrue(!OverlayPainterTest.allSet(polygonGolden, w, h, i % w, i / w)
                        && OverlayPainterTest.near(polygonGolden, w, h, i % w, i / w), "pixel " + i % w + ","
                        + i / w + " differs away from the edge");
            }
        }
        assertTrue(expected > 20000, expected + " pixels in gdal's triangle");
        assertEquals(expected, ours, expected * 0.01);
        assertTrue(differ < expected * 0.02, differ + " pixels differ");
    }

    static boolean[] golden(String name, int w, int h) throws IOException {
        Dem d = DemReader.read(OverlayPainterTest.DIR.resolve("bigtujunga_test_shapes_" + name
                + "_epsg3395_gdal_rasterize.tif"));
        assertEquals(w, d.width());
        assertEquals(h, d.height());
        boolean[] mask = new boolean[w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                mask[r * w + c] = d.get(c, r) == 255;
            }
        }
        return mask;
    }

    /** Largest alpha in columns {@code from ..< to}. */
    static int alphaIn(int[] argb, int width, int from, int to) {
        int max = 0;
        for (int i = 0; i < argb.length; i++) {
            int c = i % width;
            if (c >= from && c < to) {
                max = Math.max(max, argb[i] >>> 24);
            }
        }
        return max;
    }

    @Test
    void aLineOverTheAntimeridianIsCutAtTheMapsEdges() {
        ProjectedPicture robinson = world(MapProjection.named(ProjectionName.ROBINSON, 0), 720);
        int w = robinson.width();
        Geometry across = GF.createLineString(new Coordinate[] {new Coordinate(170, 10), new Coordinate(190, 10)});
        int[] argb = draw(robinson, lonLat(across));
        assertEquals(0, alphaIn(argb, w, w / 10, w - w / 10), "nothing across the picture");
        assertTrue(alphaIn(argb, w, 0, w / 20) > 200, "the part beyond 180° at the west edge");
        assertTrue(alphaIn(argb, w, w - w / 20, w) > 200, "the part before 180° at the east edge");

        Geometry longWay = GF.createLineString(new Coordinate[] {new Coordinate(170, 10), new Coordinate(-170, 10)});
        assertTrue(alphaIn(draw(robinson, lonLat(longWay)), w, w / 2 - 1, w / 2 + 1) > 200,
                "from 170° to −170° is the long way, through 0° (RFC 7946)");

        ProjectedPicture pacific = world(MapProjection.named(ProjectionName.ROBINSON, 150), 720);
        int[] cut = draw(pacific, lonLat(GF.createLineString(new Coordinate[] {new Coordinate(-60, 0),
                new Coordinate(0, 0)})));
        assertEquals(0, alphaIn(cut, w, w / 10, w - w / 10), "cut at −30°, the seam of a map about 150°");
        assertTrue(alphaIn(cut, w, 0, w / 10) > 200 && alphaIn(cut, w, w - w / 10, w) > 200);
    }

    @Test
    void aPolygonOverTheAntimeridianIsFilledAtBothEdges() {
        ProjectedPicture mollweide = world(MapProjection.named(ProjectionName.MOLLWEIDE, 0), 720);
        int w = mollweide.width();
        Geometry square = GF.createPolygon(new Coordinate[] {new Coordinate(170, -10), new Coordinate(190, -10),
            new Coordinate(190, 10), new Coordinate(170, 10), new Coordinate(170, -10)});
        int[] argb = draw(mollweide, new Overlay("square", List.of(square), OverlayFiles.crs84(),
                new OverlayStyle(Color.WHITE, 0, Color.WHITE, 0)));
        assertEquals(0, alphaIn(argb, w, w / 10, w - w / 10), "nothing across the picture");
        int filled = 0;
        for (int p : argb) {
            filled += (p >>> 24) >= 128 ? 1 : 0;
        }
        // Mollweide is equal-area: 20° × 20° about the equator is (2R²·20°·sin 10°) / (4πR²) of the 2:1 ellipse
        double ellipse = Math.PI / 4 * w * mollweide.height();
        double share = 2 * Math.toRadians(20) * Math.sin(Math.toRadians(10)) / (4 * Math.PI);
        assertEquals(share * ellipse, filled, 0.05 * share * ellipse, "both halves, the area of the square");
    }

    @Test
    void aLineIsCutWhereAPointCannotBeTransformedNotLeftOut() throws IOException {
        GridGeometry utm = OverlayPainterTest.grid(OverlayPainterTest.TUJUNGA);
        Coordinate a = new Coordinate(-118.3, 34.38);
        Coordinate b = new Coordinate(-118.2, 34.30);
        Coordinate beyond = new Coordinate(-118.15, 95);   // no latitude: off every map
        Coordinate d = new Coordinate(-118.1, 34.36);
        Coordinate e = new Coordinate(-118.0, 34.26);
        Overlay line = lonLat(GF.createLineString(new Coordinate[] {a, b, beyond, d, e}));
        int[] argb = OverlayPainterTest.paint(utm, List.of(line));
        int w = utm.width();
        int h = utm.height();
        assertTrue(drawnNear(argb, w, h, utm, mid(a, b)), "the run before the bad point");
        assertTrue(drawnNear(argb, w, h, utm, mid(d, e)), "the run after it");
        assertTrue(!drawnNear(argb, w, h, utm, mid(b, d)), "nothing between the runs");
    }

    private static Coordinate mid(Coordinate p, Coordinate q) {
        return new Coordinate((p.x + q.x) / 2, (p.y + q.y) / 2);
    }

    /** Whether a pixel within 2 px of the lon/lat point (placed by UTM zone 11N, as SIS computes it) is drawn. */
    private static boolean drawnNear(int[] argb, int w, int h, GridGeometry grid, Coordinate lonLat) {
        double[] xy = new double[2];
        try {
            CRS.findOperation(CommonCRS.WGS84.normalizedGeographic(), CommonCRS.WGS84.universal(34, -117), null)
                    .getMathTransform().transform(new double[] {lonLat.x, lonLat.y}, 0, xy, 0, 1);
        } catch (Exception ex) {
            throw new AssertionError(ex);
        }
        int col = (int) Math.floor((xy[0] - grid.originX()) / grid.cellWidth());
        int row = (int) Math.floor((grid.originY() - xy[1]) / grid.cellHeight());
        return OverlayPainterTest.near(argb, w, h, col, row, 2, 64);
    }
}
