package io.github.jdem846.raster;

/**
 * A request that cannot be met for a particular grid: a window outside it, or an output size that is too large or
 * too small for its cells. Only known once the grid's header is read, and the request's fault, not the file's: the
 * CLI treats it as bad usage (exit status 2). The message states the grid's size or extent and what is allowed.
 */
public final class GridRequestException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    /** Which part of the request does not fit the grid. */
    public enum Part {
        /** The window of cells or the world box. */
        WINDOW,
        /** The output size: width, height or scale. */
        SIZE
    }

    /** The part of the request that does not fit. */
    private final Part part;

    /**
     * A request that does not fit the grid.
     *
     * @param part    what does not fit
     * @param message what is wrong, with the grid's size or extent
     */
    public GridRequestException(Part part, String message) {
        super(message);
        this.part = java.util.Objects.requireNonNull(part, "part");
    }

    /** {@return the part of the request at fault} */
    public Part part() {
        return part;
    }
}
