package io.github.jdem846.overlay;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LinearRing;
import org.locationtech.jts.geom.Polygon;

/**
 * The geometries of an ESRI shapefile's {@code .shp} file (ESRI Shapefile Technical Description, 1998): points,
 * multipoints, polylines and polygons, also their Z and M variants (whose extra values are ignored). Polygon rings
 * are grouped as the format says: a clockwise ring is an outer ring, a counter-clockwise ring a hole of the outer
 * ring before it. A null shape is a null entry, so that the list matches the {@code .dbf}'s records one to one.
 */
final class ShapefileGeometries {

    private static final int FILE_CODE = 9994;
    private static final int HEADER = 100;
    private static final long MAX_BYTES = Integer.MAX_VALUE;

    private ShapefileGeometries() {
    }

    static List<Geometry> read(Path shp) throws OverlayFileException {
        ByteBuffer b;
        try (FileChannel ch = FileChannel.open(shp, StandardOpenOption.READ)) {
            long size = ch.size();
            if (size < HEADER) {
                throw new OverlayFileException(shp, "too short for a shapefile (" + size + " bytes; the header alone"
                        + " is 100)");
            }
            if (size > MAX_BYTES) {
                throw new OverlayFileException(shp, "shapefile larger than 2 GiB");
            }
            b = ch.map(FileChannel.MapMode.READ_ONLY, 0, size);
        } catch (OverlayFileException e) {
            throw e;
        } catch (IOException e) {
            throw new OverlayFileException(shp, "cannot be read (" + e.getMessage() + ")");
        }
        if (b.order(ByteOrder.BIG_ENDIAN).getInt(0) != FILE_CODE) {
            throw new OverlayFileException(shp, "not an ESRI shapefile (.shp): the file code is not 9994");
        }
        GeometryFactory gf = new GeometryFactory();
        List<Geometry> out = new ArrayList<>();
        int pos = HEADER;
        int limit = b.limit();
        while (pos + 8 <= limit) {
            int record = b.order(ByteOrder.BIG_ENDIAN).getInt(pos);
            long length = 2L * b.getInt(pos + 4);
            if (length < 4 || pos + 8 + length > limit) {
                throw new OverlayFileException(shp, "record " + record + " at byte " + pos + " claims " + length
                        + " bytes, more than the file holds (truncated or damaged)");
            }
            ByteBuffer content = b.slice(pos + 8, (int) length).order(ByteOrder.LITTLE_ENDIAN);
            try {
                out.add(shape(content, gf));
            } catch (IndexOutOfBoundsException | IllegalArgumentException e) {
                throw new OverlayFileException(shp, "record " + record + " at byte " + pos + " is damaged ("
                        + e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")");
            }
            pos += 8 + (int) length;
        }
        return out;
    }

    private static Geometry shape(ByteBuffer c, GeometryFactory gf) {
        int type = c.getInt(0);
        return switch (type) {
            case 0 -> null;
            case 1, 11, 21 -> gf.createPoint(new Coordinate(c.getDouble(4), c.getDouble(12)));
            case 8, 18, 28 -> {
                int n = count(c.getInt(36), c);
                Coordinate[] pts = new Coordinate[n];
                for (int i = 0; i < n; i++) {
                    pts[i] = new Coordinate(c.getDouble(40 + 16 * i), c.getDouble(48 + 16 * i));
                }
                yield gf.createMultiPointFromCoords(pts);
            }
            case 3, 13, 23 -> {
                List<Coordinate[]> parts = parts(c);
                yield gf.createMultiLineString(parts.stream().filter(p -> p.length >= 2)
                        .map(gf::createLineString).toArray(org.locationtech.jts.geom.LineString[]::new));
            }
            case 5, 15, 25 -> polygons(parts(c), gf);
            default -> throw new IllegalArgumentException("shape type " + type + " is not a point, multipoint,"
                    + " polyline or polygon");
        };
    }

    private static int count(int n, ByteBuffer c) {
        if (n < 0 || n > c.limit() / 16) {
            throw new IllegalArgumentException("count " + n + " does not fit the record");
        }
        return n;
    }

    /** The parts of a polyline or polygon record: bounding box, numParts, numPoints, part starts, points. */
    private static List<Coordinate[]> parts(ByteBuffer c) {
        int numParts = count(c.getInt(36), c);
        int numPoints = count(c.getInt(40), c);
        int pointsAt = 44 + 4 * numParts;
        List<Coordinate[]> parts = new ArrayList<>(numParts);
        for (int p = 0; p < numParts; p++) {
            int start = c.getInt(44 + 4 * p);
            int end = p + 1 < numParts ? c.getInt(48 + 4 * p) : numPoints;
            if (start < 0 || end < start || end > numPoints) {
                throw new IllegalArgumentException("part " + p + " spans points " + start + ".." + end + " of "
                        + numPoints);
            }
            Coordinate[] pts = new Coordinate[end - start];
            for (int i = start; i < end; i++) {
                pts[i - start] = new Coordinate(c.getDouble(pointsAt + 16 * i), c.getDouble(pointsAt + 16 * i + 8));
            }
            parts.add(pts);
        }
        return parts;
    }

    /** Clockwise rings start polygons; counter-clockwise rings are holes of the polygon before them. */
    private static Geometry polygons(List<Coordinate[]> rings, GeometryFactory gf) {
        List<Polygon> polygons = new ArrayList<>();
        LinearRing shell = null;
        List<LinearRing> holes = new ArrayList<>();
        for (Coordinate[] pts : rings) {
            if (pts.length < 4) {
                continue;
            }
            if (!pts[0].equals2D(pts[pts.length - 1])) {
                Coordinate[] closed = java.util.Arrays.copyOf(pts, pts.length + 1);
                closed[pts.length] = pts[0];
                pts = closed;
            }
            LinearRing ring = gf.createLinearRing(pts);
            if (shell == null || !Orientation.isCCW(pts)) {
                if (shell != null) {
                    polygons.add(gf.createPolygon(shell, holes.toArray(LinearRing[]::new)));
                    holes.clear();
                }
                shell = ring;
            } else {
                holes.add(ring);
            }
        }
        if (shell != null) {
            polygons.add(gf.createPolygon(shell, holes.toArray(LinearRing[]::new)));
        }
        return gf.createMultiPolygon(polygons.toArray(Polygon[]::new));
    }
}
