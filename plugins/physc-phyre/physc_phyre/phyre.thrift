// PHYRE's task structures, as far as a task file needs them: our own IDL, written from the
// facts of PHYRE's src/if/{shared,scene,task}.thrift (docs/phyre-sources.md, section 1), with
// PHYRE's names, field ids, types and enum values, so that the binary a physc task is written
// in is the binary PHYRE's loader reads.

enum Color {
  WHITE = 0,
  RED = 1,
  GREEN = 2,
  BLUE = 3,
  PURPLE = 4,
  GRAY = 5,
  BLACK = 6,
  LIGHT_RED = 7,
}

struct Vector {
  1: required double x,
  2: required double y,
}

enum BodyType {
  STATIC = 1,
  DYNAMIC = 2,
}

enum ShapeType {
  UNDEFINED = 0,
  BALL = 1,
  BAR = 2,
  JAR = 3,
  STANDINGSTICKS = 4,
}

struct Polygon {
  1: required list<Vector> vertices,
}

struct Circle {
  1: required double radius,
}

union Shape {
  1: Polygon polygon,
  2: Circle circle,
}

struct Body {
  1: required Vector position,
  2: required BodyType bodyType,
  3: optional double angle = 0.0,
  4: optional list<Shape> shapes,
  5: optional Color color,
  6: optional ShapeType shapeType = ShapeType.UNDEFINED,
  7: optional double diameter,
}

struct AbsoluteConvexPolygon {
  1: optional list<Vector> vertices,
}

struct CircleWithPosition {
  1: optional Vector position,
  2: optional double radius,
}

struct UserInput {
  1: list<AbsoluteConvexPolygon> polygons,
  2: list<CircleWithPosition> balls,
  3: list<i32> flattened_point_list,
}

enum UserInputStatus {
  UNDEFINED = 0,
  NO_OCCLUSIONS = 1,
  HAD_OCCLUSIONS = 2,
}

struct Scene {
  1: optional list<Body> bodies,
  2: optional list<Body> user_input_bodies,
  3: required i32 width,
  4: required i32 height,
  5: optional UserInputStatus user_input_status = UserInputStatus.UNDEFINED,
}

enum SpatialRelationship {
  NONE = 0,
  ABOVE = 1,
  BELOW = 2,
  LEFT_OF = 3,
  RIGHT_OF = 4,
  TOUCHING_BRIEFLY = 5,
  TOUCHING = 6,
  INSIDE = 7,
  NOT_TOUCHING = 8,
  NOT_INSIDE = 9,
}

struct Task {
  1: optional string taskId,
  2: required Scene scene,
  3: required i32 bodyId1,
  4: optional i32 bodyId2,
  5: required list<SpatialRelationship> relationships,
  6: optional string description,
  7: optional list<UserInput> solutions,
  8: optional Shape phantomShape,
  9: optional string tier,
}

struct TaskCollection {
  1: optional list<Task> tasks,
}
