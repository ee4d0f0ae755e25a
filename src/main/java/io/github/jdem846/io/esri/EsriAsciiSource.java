package io.github.jdem846.io.esri;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.io.source.ReaderGeometry;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * ESRI ASCII grid ({@code .asc}): a header of {@code key value} lines ({@code ncols}, {@code nrows},
 * {@code xllcorner|xllcenter}, {@code yllcorner|yllcenter}, {@code cellsize} or {@code dx}/{@code dy},
 * optional {@code NODATA_value}) followed by {@code nrows × ncols} decimal numbers, north row first, separated by
 * any white space. Text can only be read in order: rows are parsed forward (values outside the columns asked for,
 * and rows before them, are passed over unparsed), and a read of an earlier row starts over from the top of the
 * file. Values after the last row are ignored; a read that reaches the last row counts them and adds a notice to
 * {@link #info()}.
 */
public final class EsriAsciiSource implements RasterSource {

    private final Path file;
    private DemInfo info; // gains a notice when values follow the grid
    private boolean restCounted;
    private Tokens tokens;
    private long nextRow; // row the tokenizer stands at

    private EsriAsciiSource(Path file, DemInfo info) {
        this.file = file;
        this.info = info;
    }

    public static RasterSource open(Path asc) throws IOException {
        List<String> headerLines = new ArrayList<>();
        try (Tokens t = new Tokens(asc)) {
            t.readHeader(headerLines);
        }
        EsriHeader h = EsriHeader.parse(asc, headerLines);
        List<String> notices = new ArrayList<>();
        EsriGridLayout layout = EsriGridLayout.of(h, false, notices);
        requireRoomForValues(asc, layout);
        Double noData = h.firstNumber("nodata_value", "nodata").orElse(null);
        CrsInfo crs = SidecarCrs.resolve(asc, layout, notices);
        GridGeometry g = ReaderGeometry.of(asc, "the header's keys", layout.cols(), layout.rows(),
                layout.originX(), layout.originY(), layout.cellWidth(), layout.cellHeight(), crs, layout.anchor());
        return new EsriAsciiSource(asc, new DemInfo(asc.toString(), DemFormat.ESRI_ASCII, SampleType.TEXT, 1, g,
                noData, notices));
    }

    /**
     * Refuses a header whose ncols × nrows values cannot fit in the file: each value takes at least a character
     * and a separator, so a file of n bytes holds at most (n + 1) / 2 of them.
     */
    private static void requireRoomForValues(Path asc, EsriGridLayout layout) throws IOException {
        long size = Files.size(asc);
        long cells = (long) layout.cols() * layout.rows();
        long room = (size + 1) / 2;
        if (cells > room) {
            throw new DemFormatException(asc, "the header promises ncols × nrows = " + layout.cols() + " × "
                    + layout.rows() + " = " + cells + " values, but its " + size + " bytes hold at most " + room
                    + " (truncated, or ncols/nrows wrong?)");
        }
    }

    @Override
    public DemInfo info() {
        return info;
    }

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        int cols = info.width();
        if (tokens == null || row < nextRow) {
            if (tokens != null) {
                tokens.close();
            }
            tokens = new Tokens(file);
            tokens.readHeader(new ArrayList<>());
            nextRow = 0;
        }
        for (; nextRow < row; nextRow++) {
            for (int c = 0; c < cols; c++) {
                tokens.skipValue(nextRow, c);
            }
        }
        for (int r = 0; r < rows; r++, nextRow++) {
            for (int c = 0; c < cols; c++) {
                if (c >= col && c < col + width) {
                    dst[r * width + c - col] = tokens.nextValue(nextRow, c);
                } else {
                    tokens.skipValue(nextRow, c);
                }
            }
        }
        if (nextRow == info.height() && !restCounted) {
            restCounted = true;
            noteValuesAfterTheGrid(tokens.countRest());
        }
    }

    /** Adds a notice to {@link #info} when {@code extra} words follow the grid's nrows × ncols values. */
    private void noteValuesAfterTheGrid(long extra) {
        if (extra == 0) {
            return;
        }
        List<String> notices = new ArrayList<>(info.notices());
        notices.add(extra + (extra == 1 ? " value" : " values") + " after the grid's nrows × ncols = "
                + info.height() + " × " + info.width() + " were ignored (is the header's nrows or ncols too small?)");
        info = info.withNotices(notices);
    }

    @Override
    public void close() throws IOException {
        if (tokens != null) {
            tokens.close();
        }
    }

    /**
     * White-space separated words of the file, read from a byte buffer of its own (ISO-8859-1; white space as
     * {@link Character#isWhitespace}): a {@code Reader} read char by char costs more than twice the parsing.
     */
    private static final class Tokens implements AutoCloseable {
        private final Path file;
        private final InputStream in;
        private final byte[] buffer = new byte[1 << 16];
        private int position;
        private int limit;
        private char[] word = new char[32];
        private int wordLength;
        private String pushedBack;
        private long valuesRead;

        Tokens(Path file) throws IOException {
            this.file = file;
            this.in = Files.newInputStream(file);
        }

        /** Reads the {@code key value} pairs before the first number into {@code lines}. */
        void readHeader(List<String> lines) throws IOException {
            String w;
            while ((w = next()) != null) {
                if (isNumber(w)) {
                    pushedBack = w;
                    return;
                }
                String value = next();
                if (value == null) {
                    break;
                }
                lines.add(w + " " + value);
            }
            if (lines.isEmpty()) {
                throw new DemFormatException(file, "is not an ESRI ASCII grid: it does not start with 'ncols'");
            }
        }

        float nextValue(long row, int col) throws IOException {
            String w = next();
            if (w == null) {
                throw truncated(row, col);
            }
            valuesRead++;
            try {
                return w.equalsIgnoreCase("nan") || w.equalsIgnoreCase("-nan") ? Float.NaN : Float.parseFloat(w);
            } catch (NumberFormatException e) {
                throw new DemFormatException(file, "value '" + w + "' at row " + row + ", column " + col
                        + " is not a number");
            }
        }

        /** Passes over a value that is not wanted, without parsing it. */
        void skipValue(long row, int col) throws IOException {
            if (pushedBack != null) {
                pushedBack = null;
            } else if (!readWord()) {
                throw truncated(row, col);
            }
            valuesRead++;
        }

        /** Counts the words left up to the end of the file, passing over them. */
        long countRest() throws IOException {
            long n = 0;
            if (pushedBack != null) {
                pushedBack = null;
                n++;
            }
            while (readWord()) {
                n++;
            }
            return n;
        }

        private DemFormatException truncated(long row, int col) {
            return new DemFormatException(file, "ends after " + valuesRead + " values, at row " + row
                    + ", column " + col + "; the header promises ncols × nrows values (truncated?)");
        }

        private String next() throws IOException {
            if (pushedBack != null) {
                String w = pushedBack;
                pushedBack = null;
                return w;
            }
            return readWord() ? new String(word, 0, wordLength) : null;
        }

        /** Reads the next word into {@code word}; false at the end of the file. */
        private boolean readWord() throws IOException {
            int b;
            do {
                b = read();
            } while (b >= 0 && isWhitespace(b));
            if (b < 0) {
                return false;
            }
            wordLength = 0;
            do {
                if (wordLength == word.length) {
                    word = java.util.Arrays.copyOf(word, word.length * 2);
                }
                word[wordLength++] = (char) b;
            } while ((b = read()) >= 0 && !isWhitespace(b));
            return true;
        }

        private int read() throws IOException {
            if (position == limit) {
                limit = in.read(buffer, 0, buffer.length);
                position = 0;
                if (limit <= 0) {
                    limit = 0;
                    return -1;
                }
            }
            return buffer[position++] & 0xFF;
        }

        /** {@link Character#isWhitespace} for ISO-8859-1: tab to carriage return, the separators 28–31, space. */
        private static boolean isWhitespace(int b) {
            return b == ' ' || (b >= 9 && b <= 13) || (b >= 28 && b <= 31);
        }

        private static boolean isNumber(String w) {
            String s = w.toLowerCase(Locale.ROOT);
            if (s.equals("nan") || s.equals("-nan")) {
                return true;
            }
            try {
                Double.parseDouble(s);
                return true;
            } catch (NumberFormatException e) {
                return false;
            }
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }
}
